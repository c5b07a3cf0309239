"""Bad arguments raise ValueError (with the command's message, in Python spelling) or
TypeError, never crash."""

import math

import numpy as np
import pytest

import hypergas as hg


@pytest.mark.parametrize("kwargs, message", [
    ({"n": -5}, "n must be a number of particles in 2..2^31, got -5"),
    ({"n": 1}, "n must be a number of particles in 2..2^31, got 1"),
    ({"n": 2.5}, "n must be an integer"),
    ({"n": 1e40}, "n must be an integer"),
    ({"dim": 7}, "dim must be a dimension in 1..6, got 7"),
    ({"dim": 0}, "dim must be a dimension in 1..6"),
    ({"model": "soft"}, "model: unknown model 'soft'"),
    ({"init": "hot"}, "init: unknown initial state 'hot'"),
    ({"vhs_exponent": 0.3}, "vhs_exponent applies to --model vhs only".replace("--", "")),
    ({"model": "vhs", "vhs_exponent": 2.0}, "vhs_exponent must be in [0, 1]"),
    ({"mass_ratio": math.nan}, "mass_ratio must be a finite mass ratio > 0"),
    ({"mass_ratio": -1.0}, "mass_ratio must be a finite mass ratio > 0"),
    ({"fraction": 1.5}, "fraction must be in [0, 1]"),
    ({"temperature": 0.0}, "temperature must be a finite kT > 0"),
    ({"temperature": math.inf}, "temperature must be a finite kT > 0"),
    ({"threads": 0}, "threads must be in 1..256, got 0"),
    ({"seed": -1}, "seed must be an integer in 0..2^64-1"),
    ({"seed": 2 ** 64}, "seed must be an integer in 0..2^64-1"),
    ({"scheme": "euler"}, "unknown DSMC scheme 'euler'"),
    ({"scheme": "ntc", "dt": 0.0}, "dt must be a finite step > 0"),
    ({"dt": 0.1}, "dt applies with scheme ntc only"),
    ({"lane_size": 64}, "lane_size applies with scheme lanes only"),
    ({"scheme": "lanes", "epoch": -1.0}, "epoch must be a finite time > 0"),
    ({"n": 2 ** 40}, "n must be a number of particles in 2..2^31"),
])
def test_dsmc_bad_values(kwargs, message):
    with pytest.raises(ValueError) as e:
        hg.DSMC(**kwargs)
    assert message in str(e.value)


@pytest.mark.parametrize("kwargs, message", [
    ({"packing": 0.8}, "packing 0.8 is at or above the jamming density"),
    ({"packing": -0.1}, "packing must be a finite fraction > 0"),
    ({"packing": math.nan}, "packing must be a finite fraction > 0"),
    ({"dim": 1, "packing": 0.995}, "at most 0.99"),
    ({"packing": 0.3, "start_packing": 0.4}, "start_packing must be > 0 and at most packing 0.3"),
    ({"n": 0}, "n must be a number of particles in 2..2^31"),
])
def test_edmd_bad_values(kwargs, message):
    with pytest.raises(ValueError) as e:
        hg.EDMD(**kwargs)
    assert message in str(e.value)


@pytest.mark.parametrize("kwargs", [
    {"n": "100"}, {"n": True}, {"n": None or [3]}, {"dim": 3.0j}, {"model": 3},
    {"seed": "1"}, {"seed": 1.5}, {"mass_ratio": "2"}, {"temperature": [1.0]},
    {"scheme": 1}, {"dt": "0.1"},
])
def test_dsmc_bad_types(kwargs):
    with pytest.raises(TypeError):
        hg.DSMC(**kwargs)


def test_unknown_keyword():
    with pytest.raises(TypeError, match="did you mean 'restitution'"):
        hg.DSMC(restitutoin=0.5)  # a slip of the fingers: the nearest keyword is named
    with pytest.raises(TypeError):
        hg.DSMC(packing=0.1)  # an EDMD option
    with pytest.raises(TypeError):
        hg.EDMD(model="hs")  # a DSMC option


def test_bad_run_arguments():
    g = hg.DSMC(n=1000)
    g.run(1.0)
    for until in (math.nan, math.inf, 0.5, -1.0, 2e12):
        with pytest.raises(ValueError):
            g.run(until)
    for every in (0.0, -1.0, math.nan, 1e-9):
        with pytest.raises(ValueError):
            g.run(2.0, every=every)
    with pytest.raises(TypeError):
        g.run("2")
    with pytest.raises(TypeError):
        g.run(2.0, observers=[object()])
    with pytest.raises(TypeError):
        g.run(2.0, callback=3)
    with pytest.raises(ValueError):
        g.threads = 0
    assert g.time == 1.0  # nothing ran


def test_a_raising_callback_stops_the_run_cleanly():
    g = hg.DSMC(n=1000)

    def boom(e):
        if e.time >= 0.5:
            raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        g.run(2.0, every=0.25, callback=boom)
    assert g.time == 0.5
    g.run(1.0)
    assert g.time == 1.0


@pytest.mark.parametrize("x", [
    np.zeros(10), np.zeros((2, 3, 4)), np.zeros((1, 3)), np.zeros((5, 0)),
    np.full((5, 3), np.nan), np.array([["a", "b"], ["c", "d"]]), [[1.0, math.inf]] * 3,
])
def test_analyse_bad_arrays(x):
    with pytest.raises((ValueError, TypeError)):
        hg.analyse(x)


def test_analyse_bad_masses():
    v = np.random.default_rng(1).normal(size=(100, 3))
    for m in (np.ones(99), -np.ones(100), np.full(100, np.nan), np.zeros(100)):
        with pytest.raises(ValueError):
            hg.analyse(v, masses=m)
    with pytest.raises(ValueError):
        hg.analyse(v, bins=0)
    with pytest.raises(ValueError):
        hg.analyse(v, ks_sample=-1)


def test_analysis_functions_bad_input():
    with pytest.raises(ValueError):
        hg.maxwell_pdf(1.0, dim=0)
    with pytest.raises(ValueError):
        hg.maxwell_pdf(1.0, dim=3, kT=-1.0)
    with pytest.raises(ValueError):
        hg.maxwell_pdf(1.0, dim=3, quantity="momentum")
    with pytest.raises(ValueError):
        hg.vacf(np.zeros((10, 3)))
    with pytest.raises(ValueError):
        hg.vacf(np.zeros((1, 3, 3)))
    with pytest.raises(ValueError):
        hg.msd(np.zeros((10, 3, 3)), max_lag=10)
    with pytest.raises(ValueError):
        hg.VacfRecorder(max_particles=0)
    with pytest.raises(ValueError):
        hg.MomentsRecorder().histogram()  # nothing observed
    with pytest.raises(TypeError):
        hg.DSMC(n=100).observe(object())
