"""Analysis from Python: the command's statistics on an engine or on any velocity array."""

import dataclasses

import numpy as np

from . import _hypergas

MomentsRecorder = _hypergas.MomentsRecorder
MomentsRecorder.__doc__ = """Records one row of the command's moments.csv per observation.

MomentsRecorder(bins=50, ks_sample=0, ks_seed=..., threads=1): speed histograms of
``bins`` bins; the KS test of all speeds on fine bins (``ks_sample=0``, conservative) or
exact on at most ``ks_sample`` speeds (a reproducible random subsample above that, drawn
from its own stream seeded by ``ks_seed``). An engine's recorder reads the engine's tally,
updated at each collision; passes over arrays run on ``threads`` threads, with the same
rows for any count. Feed it with
``engine.run(..., observers=[rec])``, ``engine.observe(rec)`` or
``rec.observe_array(velocities, masses=None, time=0.0)``. ``columns`` names the columns,
``rows`` is a (observations, columns) array, ``column(name)`` one column, ``table()`` a
dict of columns, ``histogram()`` the last speed histogram (a dict; see SpeedHistogram).
"""


def _table(self):
    """The recorded rows as {column name: numpy array}."""
    rows = self.rows
    return {c: rows[:, k].copy() for k, c in enumerate(self.columns)}


MomentsRecorder.table = _table

PressureTensorRecorder = _hypergas.PressureTensorRecorder
PressureTensorRecorder.__doc__ = """The pressure tensor of a (sheared) gas: the rows of the command's
pressure_tensor.csv, one per observation.

PressureTensorRecorder(dim, shear_rate=0.0, model="hs", vhs_exponent=0.5): columns time,
real_time, temperature_ratio (T/T0, T0 of the first observation), reduced_shear_rate
(shear_rate per mean collision time at the current T), then P_ij/p for i <= j, each with
its standard error over the particles (P_xx, P_xx_err, P_xy, ...; axes x, y, z, u, v, w).
From a sheared EDMD gas the rows are the exact kinetic + collisional tensor averaged over
each interval between observations, with the interval's mean temperature and T0 that of
the start; their errors are NaN (model="hs").
``columns``, ``rows`` (an (observations, columns) array) and ``table()`` (a dict of
columns). Feed it with ``engine.run(..., observers=[rec])`` or ``engine.observe(rec)``.
"""
PressureTensorRecorder.table = _table

VacfRecorder = _hypergas.VacfRecorder
VacfRecorder.__doc__ = """Velocity autocorrelation and mean squared displacement of a run.

VacfRecorder(max_particles=1000) follows the first max_particles particles (original
numbering) through observations at equal spacing (``engine.run(until, every=dt,
observers=[rec])``) with multiple-tau correlators: memory independent of the run's length.
``lags()`` (frames), ``vacf()`` (velocity^2), ``msd()`` (length^2; EDMD only),
``green_kubo()`` (self-diffusion coefficient, length^2/time), ``dt``, ``frames``.
"""


TransportRecorder = _hypergas.TransportRecorder
TransportRecorder.__doc__ = """Green-Kubo viscosity, thermal conductivity and self-diffusion (DSMC).

TransportRecorder(dim, n, until, dt=0.05, max_lag=40, tagged=32, warmup=20, model="hs",
vhs_exponent=1, seed=1) is what ``hypergas run --transport`` uses: give it to a one-species
``DSMC`` of the same dim, n and model, observed every dt up to until (at most 1e6 samples a
``run`` call, so run in stretches: ``for t in range(1000, until + 1, 1000):
gas.run(t, every=dt, observers=[rec])``). From t = warmup on the engine keeps the
collective stress and heat flux exactly, collision by collision. ``finish()`` returns
{name: {value, error, first_sonine, ratio, ratio_error, t_cut, tail, c0, decay_rate, ...}}
for viscosity, thermal_conductivity, self_diffusion and self_diffusion_einstein, reduced by
n kT tau, n k_B (kT/m) tau and (kT/m) tau (docs/validation.md); ``normalised(g)`` the
correlation C(t)/C(0) of group g (0, 1, 2) on the grid t = k dt; ``write_transport_csv``,
``write_correlations_csv``: the command's files.
"""


HelfandRecorder = _hypergas.HelfandRecorder
HelfandRecorder.__doc__ = """Viscosity, thermal conductivity and self-diffusion of an EDMD fluid.

HelfandRecorder(dim, n, start, end, dt=0.05, max_lag=40, tagged=256, window=3) is what
``hypergas run --engine edmd --transport`` uses: give it to a one-species ``EDMD`` of the
same dim and n, observed from ``start`` to ``end`` (engine time; every observation drains
the fluxes, so the spacing of observations is free). At its first observation it measures
the mean free time tau so far and installs the Helfand moments in the engine; dt and max_lag
are in units of tau. ``finish()`` returns {name: {value, error, statistical_error,
truncation_error, first_sonine, ratio, enskog, enskog_ratio, ...}} (each integral read at
the plateau of its running integral, the remainder of its tail added and its size the
truncation error; error = sqrt(statistical^2 + truncation^2)) for viscosity (Einstein-Helfand), viscosity_green_kubo,
viscosity_kinetic, _cross, _collisional, _kinetic_point, the same for
thermal_conductivity, self_diffusion, self_diffusion_einstein (and in 3D
self_diffusion_yeh_hummer), in units sigma = m = kT = 1 (docs/validation.md).
"""

StructureRecorder = _hypergas.StructureRecorder
StructureRecorder.__doc__ = """Radial distribution function and structure factor of an EDMD fluid.

StructureRecorder(dim, n, start=0, r_max=5, dr=0.02, k_max=15, vectors_per_shell=24,
seed=1) records every observation at or after ``start``. ``finish()`` returns a dict of
numpy arrays r, g, g_error (g(r) at the bins' mean radii), k, S, S_error (shells of the
box's wave vectors), and contact, contact_error (g(sigma+)), r_max, frames.
"""


@dataclasses.dataclass(frozen=True)
class SpeedHistogram:
    """Speed histogram against the D-dimensional Maxwell-Boltzmann density at kT.

    lo, hi: bin edges (velocity units); count: particles per bin; density: count / (n
    width) (1/velocity); maxwell_density: the MB density averaged over each bin; kT:
    the reference temperature (the sample's own, 2 E_kin / (D n)); mass: the reference
    mass (mixtures: speeds are mass-weighted to the mean mass).
    """
    lo: np.ndarray
    hi: np.ndarray
    count: np.ndarray
    density: np.ndarray
    maxwell_density: np.ndarray
    kT: float
    mass: float
    dim: int
    underflow: float
    overflow: float

    @property
    def centres(self):
        return 0.5 * (self.lo + self.hi)


@dataclasses.dataclass(frozen=True)
class Analysis:
    """One row of moments.csv (the same numbers, the same code) and its speed histogram.

    m2, m4, m6: <|v|^2>, <|v|^4>, <|v|^6>; kurtosis_x: <w_x^4>/<w_x^2>^2 (MB: 3);
    m4_ratio: <w^4>/(D(D+2)(kT/m)^2) (MB: 1); each with its standard error (``*_err``).
    kT: 2 E_kin/(D n). l1_speed, kl_speed: L1 distance and KL divergence (nats) of the
    speed histogram from MB; ks_p_speed, chi2_p_speed: Kolmogorov-Smirnov and chi-square
    p-values of the speeds against MB at kT. species_kT: per-species kT (mixtures).
    """
    time: float
    collisions_per_particle: float
    m2: float
    m4: float
    kurtosis_x: float
    m6: float
    m2_err: float
    m4_err: float
    m6_err: float
    kurtosis_x_err: float
    m4_ratio: float
    m4_ratio_err: float
    kT: float
    l1_speed: float
    kl_speed: float
    ks_p_speed: float
    chi2_p_speed: float
    species_kT: tuple
    histogram: SpeedHistogram


def _histogram(d):
    return SpeedHistogram(**d)


def _analysis(rec):
    row = dict(zip(rec.columns, rec.rows[-1]))
    fields = {f.name for f in dataclasses.fields(Analysis)}
    common = {k: float(v) for k, v in row.items() if k in fields}
    species = tuple(float(v) for k, v in row.items() if k.startswith("kT_"))
    return Analysis(**common, species_kT=species, histogram=_histogram(rec.histogram()))


def analyse(x, masses=None, bins=50, ks_sample=0, ks_seed=None):
    """The command's statistics of one state: an engine, or velocities of shape (n, dim).

    For an engine, the state now (mixtures: its masses); for an array, ``masses`` (length
    n, default all 1). Returns an Analysis. The KS test is binned on all speeds, or exact on
    at most ``ks_sample`` speeds (see MomentsRecorder); everything else uses every particle.
    """
    args = (bins, ks_sample) if ks_seed is None else (bins, ks_sample, ks_seed)
    rec = MomentsRecorder(*args)
    if hasattr(x, "_h"):
        if masses is not None:
            raise ValueError("masses apply to arrays; an engine has its own")
        x._h.observe(rec)
    else:
        rec.observe_array(x, masses)
    return _analysis(rec)


def maxwell_pdf(x, dim, kT=1.0, mass=1.0, quantity="speed"):
    """The D-dimensional Maxwell-Boltzmann density of ``quantity`` ("speed", "component",
    "energy") at x (any shape), for temperature kT (energy units) and mass."""
    return _hypergas.maxwell_pdf(x, dim, kT, mass, quantity)


def maxwell_cdf(x, dim, kT=1.0, mass=1.0, quantity="speed"):
    """The cumulative Maxwell-Boltzmann distribution of ``quantity`` at x."""
    return _hypergas.maxwell_cdf(x, dim, kT, mass, quantity)


def vacf(velocities, max_lag=None):
    """<v(t0) . v(t0 + lag)> for lags 0..max_lag (default frames // 2) from equally spaced
    frames, shape (frames, n, dim), averaged over particles and time origins (FFT)."""
    return _hypergas.vacf(velocities, max_lag)


def msd(positions, max_lag=None):
    """<|r(t0 + lag) - r(t0)|^2> for lags 0..max_lag from unwrapped positions of shape
    (frames, n, dim) (EDMD.unwrapped_positions()), averaged like vacf (FFT)."""
    return _hypergas.msd(positions, max_lag)


@dataclasses.dataclass(frozen=True)
class Report:
    """The error-against-run-time study (``hypergas report``): ``points`` (study, engine,
    dim, param, run_s, error, error_se, replicas), ``slopes`` (log-log slopes of error
    against run time per curve), ``finite_n`` and ``ntc`` (bias tables), each a dict of
    numpy arrays; ``ntc_order`` p in |bias| ~ dt^p with its error; ``total_s``."""
    points: dict
    slopes: dict
    finite_n: dict
    ntc: dict
    ntc_order: float
    ntc_order_se: float
    total_s: float


def _columns(rows):
    if not rows:
        return {}
    return {k: np.array([r[k] for r in rows]) for k in rows[0]}


def report(quick=True, seed=1, threads=2):
    """Runs the error-against-run-time study of ``hypergas report`` (quick: about 20 s;
    full: minutes) and returns a Report. Errors are measured against exact values."""
    r = _hypergas.report(quick, seed, threads)
    return Report(points=_columns(r["points"]), slopes=_columns(r["slopes"]),
                  finite_n=_columns(r["finite_n"]), ntc=_columns(r["ntc"]),
                  ntc_order=r["ntc_order"], ntc_order_se=r["ntc_order_se"],
                  total_s=r["total_s"])
