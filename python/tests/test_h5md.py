"""trajectory.h5: what `hypergas run --trajectory-every` writes, read by h5py alone and by
MDAnalysis's H5MD reader (docs/h5md.md), in every dimension.

Each check is exact or to round-off: the layout of H5MD 1.1, the frames' times, energy and
momentum conserved from frame to frame (elastic gases), the observables against the
velocities they come from, EDMD positions inside the box with no two spheres overlapping,
and the packing fraction that the box and N give. Nothing here is statistical."""

import json
import math
import subprocess

import h5py
import numpy as np
import pytest


def run(cli, out, *args):
    r = subprocess.run([cli, "run", *map(str, args), "--out", str(out), "--json"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout.strip().splitlines()[-1])


def text(x):
    return x.decode() if isinstance(x, bytes) else str(x)


def check_common(f, dim, n, frames):
    assert list(f["h5md"].attrs["version"]) == [1, 1]
    assert text(f["h5md/creator"].attrs["name"]) == "hypergas"
    box = f["particles/all/box"]
    assert int(box.attrs["dimension"]) == dim
    assert len(box.attrs["boundary"]) == dim
    vel = f["particles/all/velocity"]
    assert vel["value"].shape == (frames, n, dim)
    assert vel["step"].shape == (frames,) and vel["time"].shape == (frames,)
    assert list(vel["step"][:]) == sorted(vel["step"][:])
    assert f["particles/all/species"].shape == (n,)
    assert f["particles/all/mass"].shape == (n,)
    for name in ("temperature", "a2", "collisions_per_particle"):
        assert f["observables"][name]["value"].shape == (frames,)
    v = vel["value"][:]
    m = f["particles/all/mass"][:]
    # energy and momentum per frame: conserved to round-off by an elastic gas
    e = 0.5 * np.einsum("i,fij->f", m, v * v)
    assert np.all(np.abs(e / e[0] - 1) < 1e-12)
    p = np.einsum("i,fij->fj", m, v)
    assert np.all(np.abs(p) < 1e-9 * math.sqrt(e[0] * n))
    # the observables are those of the stored velocities
    t = f["observables/temperature/value"][:]
    assert np.allclose(t, 2 * e / (dim * n), rtol=1e-12, atol=0)
    v2 = np.einsum("fij,fij->fi", v, v)
    a2 = dim / (dim + 2) * n * (v2 ** 2).sum(1) / v2.sum(1) ** 2 - 1
    assert np.allclose(f["observables/a2/value"][:], a2, rtol=1e-10, atol=1e-12)
    return v


@pytest.mark.parametrize("dim", [1, 2, 3, 4, 5, 6])
def test_dsmc_trajectory_every_dimension(tmp_path, cli, dim):
    masses = ["--mass-ratio", 3, "--fraction", 0.5] if dim == 1 else []  # 1D: two masses
    s = run(cli, tmp_path, "--engine", "dsmc", "--dim", dim, "--n", 64, "--init", "beams",
            "--until", 2, "--every", 0.25, "--trajectory-every", 0.5, "--seed", 3, *masses)
    assert s["trajectory_frames"] == 5 and s["trajectory_dt"] == 0.5
    with h5py.File(tmp_path / "trajectory.h5", "r") as f:
        check_common(f, dim, 64, 5)
        assert [text(b) for b in f["particles/all/box"].attrs["boundary"]] == ["none"] * dim
        assert "edges" not in f["particles/all/box"]
        assert "position" not in f["particles/all"]
        assert list(f["particles/all/id"][:]) == list(range(64))
        m = f["particles/all/mass"][:]
        assert sorted(set(m)) == ([1.0, 3.0] if dim == 1 else [1.0])
        assert np.allclose(f["particles/all/velocity/time"][:], [0, 0.5, 1, 1.5, 2])
        assert list(f["particles/all/velocity/step"][:]) == [0, 2, 4, 6, 8]
    assert not (tmp_path / "trajectory.h5.partial").exists()


def min_image_distances(x, L):
    d = x[:, None, :] - x[None, :, :]
    d -= L * np.round(d / L)
    r = np.sqrt((d * d).sum(-1))
    r[np.diag_indices(len(x))] = np.inf
    return r


@pytest.mark.parametrize("dim", [2, 3, 4, 5, 6])
def test_edmd_trajectory_every_dimension(tmp_path, cli, dim):
    n, packing = 100, 0.1
    s = run(cli, tmp_path, "--engine", "edmd", "--dim", dim, "--n", n, "--packing", packing,
            "--until", 3, "--equilibration", 1, "--every", 0.5, "--trajectory-every", 1,
            "--seed", 4)
    frames = s["trajectory_frames"]
    assert frames == 3  # t = 1 (the end of the equilibration), 2, 3
    with h5py.File(tmp_path / "trajectory.h5", "r") as f:
        v = check_common(f, dim, n, frames)
        box = f["particles/all/box"]
        assert [text(b) for b in box.attrs["boundary"]] == ["periodic"] * dim
        edges = box["edges/value"][:]
        assert edges.shape == (frames, dim, dim)
        L = edges[0, 0, 0]
        assert np.all(edges == np.eye(dim) * L)
        # N spheres of diameter 1 at the packing fraction asked for
        ball = math.pi ** (dim / 2) / math.gamma(dim / 2 + 1) * 0.5 ** dim
        assert abs(n * ball / L ** dim - packing) < 1e-12
        x = f["particles/all/position/value"][:]
        img = f["particles/all/image/value"][:]
        t = f["particles/all/position/time"][:]
        assert np.allclose(t, [1, 2, 3])
        assert np.all((x >= 0) & (x < L))
        assert img.dtype.kind == "i"
        for k in range(frames):
            assert min_image_distances(x[k], L).min() > 1 - 1e-9  # no overlap
        # the unwrapped motion between frames is at most the fastest speed times the interval
        u = x + img * L
        vmax = np.sqrt((v * v).sum(-1)).max()
        assert np.all(np.sqrt(((u[1:] - u[:-1]) ** 2).sum(-1)) <= vmax * 1.0 + 1e-9)


def test_mdanalysis_reads_a_3d_edmd_trajectory(tmp_path, cli):
    mda = pytest.importorskip("MDAnalysis")  # python3-mdanalysis (scripts/setup.sh --all)
    n = 108
    run(cli, tmp_path, "--engine", "edmd", "--dim", 3, "--n", n, "--packing", 0.2, "--until",
        4, "--equilibration", 1, "--every", 0.5, "--trajectory-every", 0.5, "--seed", 8)
    path = tmp_path / "trajectory.h5"
    with h5py.File(path, "r") as f:
        x = f["particles/all/position/value"][:]
        v = f["particles/all/velocity/value"][:]
        t = f["particles/all/position/time"][:]
        L = f["particles/all/box/edges/value"][0, 0, 0]
    u = mda.Universe.empty(n, trajectory=False)
    u.load_new(str(path), format="H5MD", convert_units=False)
    assert len(u.trajectory) == len(t) == 7
    for k, ts in enumerate(u.trajectory):
        assert ts.time == pytest.approx(t[k], abs=1e-12)
        # MDAnalysis keeps coordinates in single precision
        assert np.allclose(ts.positions, x[k], rtol=1e-6, atol=1e-5 * L)
        assert np.allclose(ts.velocities, v[k], rtol=1e-6, atol=1e-6)
        assert np.allclose(ts.dimensions, [L, L, L, 90, 90, 90], rtol=1e-6)


def test_no_trajectory_no_file(tmp_path, cli):
    run(cli, tmp_path, "--engine", "dsmc", "--n", 100, "--until", 1)
    assert not (tmp_path / "trajectory.h5").exists()


# ---- states from files -----------------------------------------------------------------

def write_state(path, x=None, v=None, box=None, dim=None, extra=None):
    """An H5MD file made by h5py alone, as another program would write it."""
    with h5py.File(path, "w") as f:
        f.create_group("h5md").attrs["version"] = np.array([1, 1], dtype=np.int32)
        f["h5md"].create_group("creator").attrs["name"] = "a test"
        g = f.create_group("particles/all")
        b = g.create_group("box")
        d = dim if dim is not None else v.shape[1]
        b.attrs["dimension"] = d
        b.attrs["boundary"] = np.array([b"periodic" if box else b"none"] * d)
        if box:
            b.create_dataset("edges", data=np.full(d, box))  # the vector form of the spec
        if x is not None:
            p = g.create_group("position")
            p["value"] = x[None]
            p["step"] = np.array([0])
            p["time"] = np.array([0.0])
        if v is not None:
            q = g.create_group("velocity")
            q["value"] = v[None]
            q["step"] = np.array([0])
            q["time"] = np.array([0.0])
        if extra:
            extra(f)


def cubic_lattice(n_side, a):
    g = np.arange(n_side) * a + a / 2
    return np.array(np.meshgrid(g, g, g, indexing="ij")).reshape(3, -1).T.copy()


def test_both_engines_start_from_a_file_written_by_h5py(tmp_path, cli):
    rng = np.random.default_rng(5)
    x = cubic_lattice(6, 2.0)  # 216 spheres, spacing 2 in a box of 12
    n = len(x)
    v = rng.normal(size=(n, 3))
    v -= v.mean(0)
    path = tmp_path / "start.h5"
    write_state(path, x=x, v=v, box=12.0)
    s = run(cli, tmp_path / "edmd", "--engine", "edmd", "--init-file", path, "--until", 2,
            "--trajectory-every", 0.4)
    ball = math.pi / 6
    assert s["n"] == n and s["dim"] == 3
    assert s["packing"] == pytest.approx(n * ball / 12.0 ** 3, rel=1e-12)
    assert abs(s["energy_rel_drift"]) < 1e-12
    with h5py.File(tmp_path / "edmd" / "trajectory.h5", "r") as f:
        e = 0.5 * (f["particles/all/velocity/value"][0] ** 2).sum()
        assert e == pytest.approx(0.5 * (v ** 2).sum(), rel=1e-12)  # the file's velocities
    s = run(cli, tmp_path / "dsmc", "--engine", "dsmc", "--init-file", path, "--until", 1,
            "--trajectory-every", 1)
    assert s["n"] == n and s["dim"] == 3
    with h5py.File(tmp_path / "dsmc" / "trajectory.h5", "r") as f:
        assert np.array_equal(f["particles/all/velocity/value"][0], v)  # frame 0 is the file's


def test_an_edmd_run_from_a_frame_continues_the_run(tmp_path, cli):
    # One run, frames every 0.5 from t = 1; a second run from its frame at t = 2. EDMD is
    # deterministic: the second run's frames at 0.5 and 1 are the first's at 2.5 and 3, up
    # to the rounding of the synchronised start (the chaos of hard spheres grows it by a few
    # orders of magnitude in one time unit; measured below 1e-12).
    common = ["--engine", "edmd", "--every", 0.5, "--trajectory-every", 0.5]
    run(cli, tmp_path / "a", *common, "--dim", 3, "--n", 500, "--packing", 0.1, "--until", 4,
        "--equilibration", 1, "--seed", 9)
    a = tmp_path / "a" / "trajectory.h5"
    run(cli, tmp_path / "b", *common, "--init-file", a, "--init-frame", 2, "--until", 1,
        "--equilibration", 0.5)
    with h5py.File(a, "r") as fa, h5py.File(tmp_path / "b" / "trajectory.h5", "r") as fb:
        ta, tb = fa["particles/all/position/time"][:], fb["particles/all/position/time"][:]
        assert ta[2] == 2.0 and list(tb) == [0.5, 1.0]
        L = fa["particles/all/box/edges/value"][0, 0, 0]
        for kb, ka in ((0, 3), (1, 4)):
            ua = fa["particles/all/position/value"][ka]
            ub = fb["particles/all/position/value"][kb]
            d = ub - ua
            d -= L * np.round(d / L)  # the same point seen across a face
            assert np.abs(d).max() < 1e-8
            va = fa["particles/all/velocity/value"][ka]
            vb = fb["particles/all/velocity/value"][kb]
            assert np.abs(va - vb).max() < 1e-8


BAD = [
    # (what, make(path), extra options, the message's words)
    ("not HDF5", lambda p: p.write_text("x,y\n1,2\n"), [], "not an HDF5 file"),
    ("not H5MD", lambda p: h5py.File(p, "w").create_dataset("a", data=[1]), [], "not an H5MD file"),
    ("no velocity", lambda p: write_state(p, x=cubic_lattice(3, 2.0), box=6.0, dim=3), [],
     "has no velocity"),
    ("NaN", lambda p: write_state(p, v=np.array([[np.nan, 0, 0], [1, 0, 0]])), [],
     "not finite"),
    ("other D", lambda p: write_state(p, v=np.ones((4, 2)) * [[1], [-1], [1], [-1]]),
     ["--dim", 3], "differs from the dimension 2"),
    ("other N", lambda p: write_state(p, v=np.ones((4, 3)) * [[1], [-1], [1], [-1]]),
     ["--n", 5], "differs from the 4 particles"),
    ("no frame 3", lambda p: write_state(p, v=np.ones((4, 3)) * [[1], [-1], [1], [-1]]),
     ["--init-frame", 3], "frame 3 does not exist"),
    ("overlap", lambda p: write_state(p, x=np.array([[1.0, 1, 1], [1.5, 1, 1], [4, 4, 4]]),
                                      v=np.array([[1.0, 0, 0], [-1, 0, 0], [0, 0, 0]]), box=8.0),
     ["--engine", "edmd"], "particles 0 and 1 overlap"),
    ("EDMD without positions", lambda p: write_state(p, v=np.ones((4, 3)) * [[1], [-1], [1], [-1]]),
     ["--engine", "edmd"], "holds no positions"),
    ("with --init", lambda p: write_state(p, v=np.ones((4, 3)) * [[1], [-1], [1], [-1]]),
     ["--init", "maxwell"], "describes a generated start"),
]


@pytest.mark.parametrize("what,make,extra,words", BAD, ids=[b[0] for b in BAD])
def test_bad_init_files_exit_2_and_write_nothing(tmp_path, cli, what, make, extra, words):
    path = tmp_path / "bad.h5"
    make(path)
    out = tmp_path / "out"
    r = subprocess.run([cli, "run", "--init-file", str(path), *map(str, extra), "--out",
                        str(out)], capture_output=True, text=True)
    assert r.returncode == 2, (what, r.stderr)
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and words in lines[0], (what, r.stderr)
    assert not out.exists()


def test_a_truncated_trajectory_is_refused(tmp_path, cli):
    run(cli, tmp_path / "a", "--engine", "dsmc", "--n", 2000, "--until", 2,
        "--trajectory-every", 0.5)
    data = (tmp_path / "a" / "trajectory.h5").read_bytes()
    cut = tmp_path / "cut.h5"
    cut.write_bytes(data[: len(data) // 2])
    r = subprocess.run([cli, "run", "--init-file", str(cut), "--out", str(tmp_path / "o")],
                       capture_output=True, text=True)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert not (tmp_path / "o").exists()


def test_example_12_runs_as_written(tmp_path, cli):
    """examples/12-configurations: the README's three commands, in a scratch folder."""
    import os
    import pathlib
    import sys
    root = pathlib.Path(__file__).resolve().parents[2]
    ex = root / "examples" / "12-configurations"
    subprocess.run([cli, "run", "--engine", "edmd", "--dim", "4", "--n", "5000", "--packing",
                    "0.25", "--start-packing", "0.1", "--until", "12", "--equilibration", "2",
                    "--every", "0.1", "--trajectory-every", "0.5", "--out", "out/dense4"],
                   cwd=tmp_path, check=True, capture_output=True)
    subprocess.run([cli, "sweep", str(ex / "restart.toml"), "--out", "out/restart4"],
                   cwd=tmp_path, check=True, capture_output=True)
    env = dict(os.environ)
    r = subprocess.run([sys.executable, str(ex / "analyse.py"), "out/dense4", "out/restart4"],
                       cwd=tmp_path, check=True, capture_output=True, text=True, env=env)
    assert "saved: 21 frames of 5000 spheres in D = 4" in r.stdout
    assert "runs from frames 1..20" in r.stdout


def test_engine_run_writes_a_trajectory(tmp_path):
    """engine.run(until, every, trajectory=PATH): a frame at each sampling instant."""
    import hypergas as hg
    md = hg.EDMD(dim=3, n=108, packing=0.2, seed=3)
    md.run(1.0)
    path = tmp_path / "md.h5"
    md.run(3.0, every=0.5, trajectory=path)
    t = hg.read_trajectory(path)
    assert list(t.time) == [1.0, 1.5, 2.0, 2.5, 3.0] and t.n == 108 and t.dim == 3
    order = np.argsort(md.ids)  # rows in memory order; the file is in particle order
    assert np.array_equal(t.velocities[-1], md.velocities[order])
    d = t.positions[-1] - md.positions[order]
    d -= t.box[-1] * np.round(d / t.box[-1])
    assert np.abs(d).max() < 1e-12
    g = hg.DSMC(dim=4, n=500, init="beams", seed=2)
    g.run(2.0, every=1.0, trajectory=tmp_path / "g.h5")
    t = hg.read_trajectory(tmp_path / "g.h5")
    assert len(t) == 3 and t.positions is None
    assert np.array_equal(t.velocities[-1], g.velocities)


def test_two_masses_from_a_file(tmp_path, cli):
    """Mass 1 is species 0, the other mass species 1: the run's mass ratio and fraction."""
    rng = np.random.default_rng(11)
    x = cubic_lattice(4, 2.5)  # 64 spheres in a box of 10
    n = len(x)
    m = np.where(np.arange(n) % 4 == 0, 3.0, 1.0)  # 16 of mass 3
    v = rng.normal(size=(n, 3))
    v -= (m[:, None] * v).sum(0) / m.sum()  # zero total momentum
    path = tmp_path / "two.h5"

    def masses(f):
        f["particles/all/mass"] = m
        f["particles/all/species"] = (m != 1).astype(np.int32)

    write_state(path, x=x, v=v, box=10.0, extra=masses)
    for engine in ("dsmc", "edmd"):
        s = run(cli, tmp_path / engine, "--engine", engine, "--init-file", path, "--until", 1,
                "--trajectory-every", 1)
        assert s["mass_ratio"] == 3.0 and s["fraction"] == 0.25, engine
        with h5py.File(tmp_path / engine / "trajectory.h5", "r") as f:
            assert np.array_equal(f["particles/all/mass"][:], m), engine
            assert np.array_equal(f["particles/all/species"][:], (m != 1).astype(np.int32))
    three = tmp_path / "three.h5"
    write_state(three, v=v, extra=lambda f: f["particles/all"].create_dataset(
        "mass", data=np.where(np.arange(n) % 2 == 0, 2.0, np.where(np.arange(n) % 3, 1.0, 5.0))))
    r = subprocess.run([cli, "run", "--init-file", str(three), "--out", str(tmp_path / "o")],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "more than two masses" in r.stderr
