"""Uniform shear flow from Python: the shear_rate and thermostat keywords of hypergas.DSMC,
the steady shear stress of Maxwell molecules against the exact rheology
(docs/validation.md, "Uniform shear flow"), the held temperature of the isokinetic
thermostat, and bad values."""

import math

import numpy as np
import pytest

import hypergas as hg


def maxwell_shear_3d(a, n):
    """P_xy / p and P_yy / p of the steady state (r = N / (2 (N - 1)); in 3D the thermostat
    rate has the closed form of Garzo and Santos)."""
    r = n / (2.0 * (n - 1.0))
    zeta = r * (2.0 / 3.0) * math.sinh(math.acosh(1.0 + 9.0 * (a / r) ** 2) / 6.0) ** 2
    return -a * r / (r + 2 * zeta) ** 2, r / (r + 2 * zeta)


def pressure(v):
    p = v.T @ v / (len(v) - 1)
    return p / (np.trace(p) / v.shape[1])


@pytest.mark.parametrize("thermostat", ["none", "isokinetic"])
def test_maxwell_shear_stress(thermostat):
    # N = 50000, samples every 0.5 over [20, 120]: 201 samples, 10 blocks of 10 mean
    # collision times; 5 block standard errors (t with 9 dof: P(|t| > 5) = 7.4e-4 per
    # comparison, two comparisons)
    n, a = 50_000, 1.0
    g = hg.DSMC(dim=3, n=n, model="maxwell", init="maxwell", seed=5, shear_rate=a,
                thermostat=thermostat)
    g.run(20.0)
    t0 = g.temperature
    xy, yy = [], []
    rec = hg.PressureTensorRecorder(3, shear_rate=a, model="maxwell")
    for k in range(201):
        g.run(20.0 + 0.5 * k)
        g.observe(rec)
        p = pressure(g.velocities)
        xy.append(p[0, 1])
        yy.append(p[1, 1])
    # the recorder's rows are the command's pressure_tensor.csv: the same tensor
    table = rec.table()
    assert np.allclose(table["P_xy"], xy, rtol=0, atol=1e-12)
    assert np.allclose(table["P_yy"], yy, rtol=0, atol=1e-12)
    assert np.all(table["reduced_shear_rate"] == pytest.approx(a, rel=1e-12))
    for k in range(201):
        if thermostat == "isokinetic":
            assert table["temperature_ratio"][k] == pytest.approx(1.0, rel=1e-12)
    if thermostat == "isokinetic":
        assert g.temperature == pytest.approx(t0, rel=1e-12)
    exact_xy, exact_yy = maxwell_shear_3d(a, n)
    for series, exact in ((xy, exact_xy), (yy, exact_yy)):
        blocks = np.array(series[:200]).reshape(10, 20).mean(axis=1)
        se = blocks.std(ddof=1) / math.sqrt(10)
        assert abs(blocks.mean() - exact) <= 5 * se, (blocks.mean(), se, exact)
    if thermostat == "none":
        assert g.temperature > 10 * t0  # viscous heating: T grows as exp(2 zeta t)


def test_edmd_lees_edwards_against_dsmc():
    """hypergas.EDMD(shear_rate=, thermostat=): the dilute 2D gas under Lees-Edwards
    boundaries against the DSMC engine's Boltzmann hard spheres at the same a (per
    ideal-gas mean collision time). The EDMD rows are exact interval means of the kinetic +
    collisional tensor. At packing 0.005 the Enskog terms shift P_xy/p by ~0.2 %
    (docs/validation.md, "Uniform shear flow in EDMD"); the tolerance is that 0.5 % plus 5
    combined block standard errors (10 blocks each, t with 9 dof: 7.4e-4 per comparison)."""
    a = 0.5
    d = hg.DSMC(dim=2, n=40_000, model="hs", init="maxwell", seed=3, shear_rate=a,
                thermostat="isokinetic")
    rd = hg.PressureTensorRecorder(2, shear_rate=a, model="hs")
    d.run(10.0)
    d.run(110.0, every=0.5, observers=[rd])
    eta = 0.005
    nu0 = 2 * 4 * eta / math.sqrt(math.pi)  # ideal-gas collisions per unit time
    e = hg.EDMD(dim=2, n=4000, packing=eta, seed=3, shear_rate=a, thermostat="isokinetic")
    re = hg.PressureTensorRecorder(2, shear_rate=a, model="hs")
    e.run(10.0 / nu0)
    e.run(110.0 / nu0, every=0.5 / nu0, observers=[re])
    te = re.table()
    # the interval-mean temperature is held at T0 (the thermostat's rescalings)
    assert np.mean(te["temperature_ratio"][1:]) == pytest.approx(1.0, abs=2e-3)

    def mean_se(x):
        b = np.asarray(x[1:201]).reshape(10, 20).mean(axis=1)
        return b.mean(), b.std(ddof=1) / math.sqrt(10)

    for key in ("P_xy", "P_yy"):
        (md, sd), (me, se) = mean_se(rd.table()[key]), mean_se(te[key])
        tol = 0.005 * abs(md) + 5 * math.hypot(sd, se)
        assert abs(me - md) <= tol, (key, me, se, md, sd)


@pytest.mark.parametrize("kw,message", [
    (dict(shear_rate=-1.0), "shear_rate"),
    (dict(shear_rate=math.nan), "shear_rate"),
    (dict(thermostat="isokinetic"), "needs shear_rate > 0"),
    (dict(shear_rate=1.0, scheme="lanes"), "exact only"),
    (dict(shear_rate=1.0, thermostat="isokinetic", restitution=0.9), "elastic gas"),
])
def test_bad_shear_values(kw, message):
    with pytest.raises(ValueError, match=message):
        hg.DSMC(dim=3, n=100, **kw)
    with pytest.raises(ValueError, match="dim >= 2"):
        hg.DSMC(dim=1, n=100, mass_ratio=3.0, shear_rate=1.0)


def test_example_13_runs(tmp_path, cli):
    """examples/13-shear: its commands on smaller plans (2 dimensions, 2 shear rates,
    fewer particles and a shorter time), then analyse.py."""
    import os
    import pathlib
    import subprocess
    import sys
    ex = pathlib.Path(__file__).resolve().parents[2] / "examples" / "13-shear"
    cli = os.path.abspath(cli)
    for name in ("maxwell", "hs"):
        plan = (ex / f"{name}.toml").read_text()
        for a, b in (("n = 20000", "n = 4000"), ("until = 120", "until = 60"),
                     ("dim = [2, 3, 4, 5, 6]", "dim = [2, 5]"),
                     ("shear_rate = [0.25, 0.5, 1, 2, 4]", "shear_rate = [0.5, 2]")):
            assert a in plan
            plan = plan.replace(a, b)
        (tmp_path / f"{name}.toml").write_text(plan)
        subprocess.run([cli, "sweep", f"{name}.toml", "--out", f"out/usf-{name}"],
                       cwd=tmp_path, check=True, capture_output=True)
    subprocess.run([cli, "run", "--model", "hs", "--dim", "3", "--n", "20000", "--init",
                    "maxwell", "--shear-rate", "2", "--thermostat", "isokinetic", "--until",
                    "30", "--every", "0.5", "--trajectory-every", "10", "--out", "out/usf3"],
                   cwd=tmp_path, check=True, capture_output=True)
    subprocess.run([cli, "run", "--model", "hs", "--dim", "3", "--n", "5000", "--init",
                    "maxwell", "--restitution", "0.9", "--shear-rate", "1", "--until", "100",
                    "--out", "out/granular"], cwd=tmp_path, check=True, capture_output=True)
    r = subprocess.run([sys.executable, str(ex / "analyse.py"), "out/usf-maxwell",
                        "out/usf-hs", "out/usf3", "out/granular"], cwd=tmp_path, check=True,
                       capture_output=True, text=True,
                       env=dict(os.environ, PYTHONPATH=str(pathlib.Path(hg.__file__)
                                                           .resolve().parents[1])))
    worst = float(r.stdout.split("largest Maxwell deviation: ")[1].split()[0])
    assert worst < 5.0, r.stdout  # 4 cases, each within 5 se: false failure below 3e-3
    assert "tails: 3D hard spheres at a = 2, 3 frames of 20000 particles" in r.stdout
    assert "granular steady state" in r.stdout


def test_edmd_sheared_temperature_is_peculiar_and_z_undefined(tmp_path):
    """Under Lees-Edwards shear every temperature is that of the peculiar velocities
    c = v - a (y - L/2) e_x (edmd/lees_edwards.hpp), the lab velocities of ``velocities``
    less the streaming profile: ``temperature`` equals it to round-off (an identity of the
    engine's sums), while the lab-frame value is larger by the profile's a^2 L^2 / (12 D)
    (24 at packing 0.2, a = 0.5 per ideal collision time, N = 4000). Z = PV/(N kT) is an
    equilibrium measurement: NaN, as the command's summary says, and a trajectory (a
    periodic H5MD box, no Lees-Edwards offset) is refused."""
    eta, a = 0.2, 0.5
    e = hg.EDMD(dim=3, n=4000, packing=eta, seed=5, shear_rate=a, thermostat="isokinetic")
    e.run(3.0)
    x, v = np.array(e.positions), np.array(e.velocities)
    rate = a * 3 * 2**3 * eta / math.sqrt(math.pi)  # a nu0 at kT0 = 1 (unit mass)
    c = v.copy()
    c[:, 0] -= rate * (x[:, 1] - e.box_side / 2)
    peculiar = (c**2).sum() / (3 * e.n)
    lab = (v**2).sum() / (3 * e.n)
    assert e.temperature == pytest.approx(peculiar, rel=1e-10)
    assert e.temperature == pytest.approx(1.0, abs=0.05)  # held by the thermostat
    assert lab - peculiar == pytest.approx(rate**2 * e.box_side**2 / 36, rel=0.05)
    assert math.isnan(e.pressure_Z)
    with pytest.raises(ValueError, match="cannot be combined with shear_rate"):
        e.run(4.0, trajectory=tmp_path / "t.h5")


def test_edmd_sheared_summary_kt_is_moments_kt(tmp_path, cli):
    """The command's summary kT is the peculiar temperature that moments.csv's last row
    holds (the same sum at the same instant: equal to round-off), the streaming energy has
    its own key (a^2 L^2 / 24 per particle within the 5 % of a finite gas's fluctuating
    heights), and stdout says that Z is undefined rather than quoting an error for it."""
    import csv
    import json
    import subprocess
    eta, a = 0.2, 0.5
    r = subprocess.run([cli, "run", "--engine", "edmd", "--dim", "3", "--n", "4000",
                        "--packing", str(eta), "--shear-rate", str(a), "--thermostat",
                        "isokinetic", "--until", "3", "--out", str(tmp_path), "--json"],
                       capture_output=True, text=True, check=True)
    s = json.loads(r.stdout.strip().splitlines()[-1])
    with open(tmp_path / "moments.csv") as f:
        last = list(csv.DictReader(f))[-1]
    assert s["kT"] == pytest.approx(float(last["kT"]), rel=1e-9)
    assert s["kT"] == pytest.approx(1.0, abs=0.05)
    rate = a * s["ideal_collision_rate"]
    L = (4000 * math.pi / 6 / eta) ** (1 / 3)
    assert s["streaming_kinetic_energy"] == pytest.approx(rate**2 * L**2 / 24, rel=0.05)
    assert s["Z"] is None and s["Z_error"] is None
    # no equilibrium self-diffusion either: the MSD grows with the flow
    assert s["diffusion_green_kubo"] is None and s["diffusion_einstein"] is None
    assert "warning" not in r.stderr
    z_line = [l for l in r.stdout.splitlines() if "PV/NkT" in l]
    assert z_line and "undefined under shear" in z_line[0] and "+-" not in z_line[0].split(
        "collision rate")[0]
