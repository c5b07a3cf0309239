"""Analysis from Python against exact results."""

import math

import numpy as np
import pytest

import hypergas as hg


@pytest.mark.parametrize("dim", range(1, 7))
def test_maxwell_density_is_normalised_with_the_right_mean_square(dim):
    v = np.linspace(0.0, 12.0, 240001)
    p = hg.maxwell_pdf(v, dim, kT=1.5, mass=2.0)
    # trapezoid rule, error ~ h^2 f'' / 12 ~ 1e-10 here
    assert np.trapz(p, v) == pytest.approx(1.0, abs=1e-9)
    # <v^2> = D kT / m
    assert np.trapz(p * v * v, v) == pytest.approx(dim * 1.5 / 2.0, rel=1e-9)
    assert hg.maxwell_cdf(12.0, dim, kT=1.5, mass=2.0) == pytest.approx(1.0, abs=1e-12)


def test_analyse_accepts_maxwell_samples_and_rejects_others():
    rng = np.random.default_rng(2024)
    v = rng.normal(size=(400000, 3))
    a = hg.analyse(v)
    # exact MB samples: KS p uniform (P(p < 1e-3) = 1e-3); kurtosis within 4 standard
    # errors (probability 6e-5 of failing with another seed); kT within 4 se of
    # sqrt(2/(3n)) relative
    assert a.ks_p_speed > 1e-3
    assert abs(a.kurtosis_x - 3.0) < 4 * a.kurtosis_x_err
    assert abs(a.kT - 1.0) < 4 * math.sqrt(2.0 / (3 * 400000))
    # the histogram's counts are every particle, its MB density integrates to ~1
    h = a.histogram
    assert h.count.sum() + h.underflow + h.overflow == 400000
    assert np.sum(h.maxwell_density * (h.hi - h.lo)) == pytest.approx(1.0, abs=1e-3)
    # power: a uniform cube of the same kT is far from MB
    u = rng.uniform(-1.0, 1.0, size=(400000, 3))
    b = hg.analyse(u)
    assert b.ks_p_speed < 1e-30 and b.chi2_p_speed < 1e-30
    assert abs(b.kurtosis_x - 1.8) < 4 * b.kurtosis_x_err


def test_analyse_of_an_engine_equals_analyse_of_its_view():
    g = hg.DSMC(dim=5, n=20000, init="beams", seed=4).run(0.7)
    a, b = hg.analyse(g), hg.analyse(g.velocities)
    for f in ("m2", "m4", "kurtosis_x", "kT", "l1_speed", "ks_p_speed", "chi2_p_speed"):
        assert getattr(a, f) == getattr(b, f), f
    np.testing.assert_array_equal(a.histogram.count, b.histogram.count)
    # a copy in another layout gives the same numbers too
    c = hg.analyse(np.ascontiguousarray(g.velocities))
    assert c.m4 == a.m4 and c.ks_p_speed == a.ks_p_speed


def test_mixture_analysis_with_masses():
    g = hg.DSMC(dim=3, n=20000, mass_ratio=9.0, init="two-temp", seed=1)
    a = hg.analyse(g)
    assert len(a.species_kT) == 2
    b = hg.analyse(g.velocities, masses=g.masses)
    assert b.kT == pytest.approx(a.kT, rel=1e-12)
    assert b.m4_ratio == pytest.approx(a.m4_ratio, rel=1e-12)


def test_vacf_and_msd_of_exact_motions():
    rng = np.random.default_rng(5)
    n, frames = 50, 64
    v0 = rng.normal(size=(n, 2))
    vel = np.broadcast_to(v0, (frames, n, 2)).copy()
    # constant velocities: vacf(lag) = <|v|^2> for every lag
    np.testing.assert_allclose(hg.vacf(vel, 20), np.mean(np.sum(v0 ** 2, axis=1)), rtol=1e-12)
    # ballistic motion r = r0 + v t: msd(lag) = <|v|^2> lag^2
    t = np.arange(frames)[:, None, None]
    r = rng.normal(size=(n, 2)) + v0 * t
    lags = np.arange(21)
    np.testing.assert_allclose(hg.msd(r, 20), np.mean(np.sum(v0 ** 2, axis=1)) * lags ** 2,
                               rtol=1e-9, atol=1e-9)


def test_vacf_recorder_on_an_edmd_run():
    g = hg.EDMD(dim=3, n=2000, packing=0.2, seed=6)
    g.run(2.0)
    rec = hg.VacfRecorder(max_particles=2000)
    g.run(12.0, every=0.05, observers=[rec])
    c = rec.vacf()
    # vacf(0) = <|v|^2> = D kT / m of the recorded particles: kT = 1 up to finite-sample
    # noise, sqrt(2 / (3 n)) relative (4 se bound)
    assert abs(c[0] / 3.0 - 1.0) < 4 * math.sqrt(2.0 / (3 * 2000))
    assert c[-1] < 0.05 * c[0]  # decorrelated after 5 time units at this density
    m = rec.msd()
    assert m[0] == 0.0 and np.all(np.diff(m) > 0)
    # Einstein and Green-Kubo agree on the self-diffusion coefficient (same run) within 15 %
    lags = rec.lags() * rec.dt
    slope = (m[-1] - m[len(m) // 2]) / (lags[-1] - lags[len(m) // 2])
    assert rec.green_kubo() == pytest.approx(slope / 6.0, rel=0.15)


def test_moments_recorder_rows_and_histogram():
    g = hg.DSMC(dim=2, n=5000, seed=1)
    rec = hg.MomentsRecorder(bins=20)
    g.run(1.0, every=0.5, observers=[rec])
    assert rec.rows.shape == (3, len(rec.columns))
    h = rec.histogram()
    assert len(h["lo"]) == 20 and h["count"].sum() + h["underflow"] + h["overflow"] == 5000


def test_report_quick():
    r = hg.report(quick=True, seed=1, threads=2)
    stat = r.slopes["study"] == "stat"
    # statistical regime: RMS error ~ (run time)^(-1/2); the quick report's slopes carry
    # fit errors of ~0.1, so each lies within 5 of its own standard errors of -1/2
    assert stat.any()
    for s, se in zip(r.slopes["slope"][stat], r.slopes["slope_se"][stat]):
        assert abs(s + 0.5) < 5 * se + 0.15
    assert len(r.points["error"]) > 0 and np.all(r.points["error"] > 0)


def test_transport_recorder_maxwell_molecules_exact_rates():
    # Maxwell molecules in 3D: the stress and tagged-velocity correlations decay exactly at
    # N/(2(N-1)), the heat flux at (D-1)/(2D) N/(N-1) (docs/validation.md); 4 standard
    # errors from 32 stretches (false failure about 3e-4 each, Student t, 31 dof)
    n, until = 400, 3020.0
    gas = hg.DSMC(dim=3, n=n, model="maxwell", init="maxwell", seed=5)
    rec = hg.TransportRecorder(3, n, until, max_lag=20.0, tagged=16, model="maxwell")
    for t in (1020.0, 2020.0, until):
        gas.run(t, every=0.05, observers=[rec])
    r = rec.finish()
    f = n / (n - 1.0)
    exact = {"viscosity": 0.5 * f, "thermal_conductivity": f / 3.0, "self_diffusion": 0.5 * f}
    for name, rate in exact.items():
        c = r[name]
        assert abs(c["decay_rate"] - rate) < 4 * c["decay_rate_error"], (name, c)
        assert abs(c["value"] - c["c0"] / rate) < 4 * c["error"], (name, c)
    assert rec.normalised(0)[0] == 1.0
    assert r["self_diffusion_einstein"]["value"] == pytest.approx(r["self_diffusion"]["value"],
                                                                 rel=0.01)


def test_transport_recorder_bad_input():
    with pytest.raises(ValueError):
        hg.TransportRecorder(1, 100, 1000.0)
    with pytest.raises(ValueError):
        hg.TransportRecorder(3, 100, 100.0)  # shorter than ten correlation windows
    with pytest.raises(ValueError):
        hg.TransportRecorder(3, 100, 1000.0, model="soft")
    gas = hg.DSMC(dim=3, n=200, mass_ratio=2.0, seed=1)
    rec = hg.TransportRecorder(3, 200, 1000.0, warmup=0.0)
    with pytest.raises(ValueError):
        gas.run(1.0, every=0.05, observers=[rec])


def test_edmd_structure_and_transport_recorders():
    # 3D at eta = 0.3: the contact value from the rdf equals the contact theorem's from Z
    # (errors from 16 stretches: 5 se plus the 0.5 % extrapolation bound, as the C++ test),
    # and the Helfand and Green-Kubo viscosities of the same run agree within their errors
    gas = hg.EDMD(dim=3, n=500, packing=0.3, seed=4)
    gas.run(10.0)
    z0 = gas.pressure_Z
    st = hg.StructureRecorder(3, 500, start=10.0, r_max=2.5, k_max=4.0)
    tr = hg.HelfandRecorder(3, 500, 10.0, 300.0, max_lag=20.0)
    gas.run(300.0, every=0.5, observers=[st, tr])
    s = st.finish()
    assert s["frames"] == 581
    assert s["g"].shape == s["r"].shape == s["g_error"].shape
    c = 4 * 0.3
    z = 1 + c * s["contact"]
    assert z0 > 1.0
    assert abs(gas.pressure_Z - z) <= c * (5 * s["contact_error"] + 0.005 * s["contact"])
    t = tr.finish()
    assert tr.chi == pytest.approx(s["contact"], rel=0.05)
    v, g = t["viscosity"], t["viscosity_green_kubo"]
    assert abs(v["value"] - g["value"]) < 4 * max(v["error"], g["error"])
    assert v["stretches"].shape == (32,)
    assert t["self_diffusion"]["enskog"] > 0


def test_edmd_recorders_bad_input():
    with pytest.raises(ValueError):
        hg.HelfandRecorder(1, 100, 0.0, 100.0)
    with pytest.raises(ValueError):
        hg.HelfandRecorder(3, 100, 10.0, 5.0)  # end before start
    with pytest.raises(ValueError):
        hg.StructureRecorder(3, 100, r_max=0.5)
    gas = hg.EDMD(dim=3, n=200, packing=0.2, seed=1)
    gas.run(2.0)
    rec = hg.HelfandRecorder(3, 200, 2.0, 4.0)  # far shorter than two correlation windows
    with pytest.raises(ValueError):
        gas.run(4.0, every=0.5, observers=[rec])


def test_vacf_recorder_diffusion_is_the_commands_estimator():
    """VacfRecorder.diffusion: the command's diffusion_* keys (one plateau rule,
    sim/outputs/vacf.cpp) from Python: Green-Kubo and Einstein of one run agree within 3
    combined errors (they share the trajectory, so the combined error overstates their
    difference: conservative), and the errors are finite and positive."""
    import math
    e = hg.EDMD(dim=3, n=2000, packing=0.3, seed=2)
    e.run(5)
    r = hg.VacfRecorder(2000)
    e.run(25, every=0.02, observers=[r])
    d = r.diffusion(e.mean_free_time)
    assert d["statistical_error"] > 0 and d["truncation_error"] >= 0
    assert d["error"] == pytest.approx(math.hypot(d["statistical_error"],
                                                  d["truncation_error"]))
    assert abs(d["green_kubo"] - d["einstein"]) <= 3 * math.hypot(d["error"],
                                                                  d["einstein_error"])
    # the self-diffusion of the dense 3D fluid: between 0.1 and 0.3 (sigma sqrt(kT/m))
    assert 0.1 < d["green_kubo"] < 0.3
