"""The engines: DSMC and EDMD, thin Python classes over the compiled handles."""

import inspect
import math
import os

import numpy as np

from . import _hypergas
from ._progress import Progress


class _Engine:
    """What both engines share: the run loop, the clock, the velocity view."""

    _kind = ""

    def __init__(self, handle):
        self._h = handle
        self._observed_at = None  # engine time of the last observation (none twice)

    # ---- running ------------------------------------------------------------------
    def run(self, until, every=None, callback=None, observers=(), progress=False,
            trajectory=None):
        """Advances the gas to time ``until`` and returns the engine.

        With ``observers`` (MomentsRecorder, VacfRecorder, TransportRecorder, HelfandRecorder,
        StructureRecorder) or a ``callback`` (called as
        ``callback(engine)``), they are called at the instants of ``hypergas run --every``:
        K + 1 evenly spaced times from t0 (the time at the call) to ``until``, K =
        round((until - t0) / every) (at least 1; 50 without ``every``), so ``every`` is
        rounded to divide the span and the last call is at ``until``. An instant already
        observed by the previous run is not observed again. A run with the same seed and
        ``every`` gives the command's trajectory and moments.csv rows bit for bit (DSMC), or
        the same trajectory whatever the stops (EDMD).

        The GIL is released while the engine runs. Ctrl-C raises KeyboardInterrupt within
        about 0.1 s (DSMC: at the end of the current epoch of ~2N candidates) and leaves
        the engine consistent at the time it reached; ``run`` can then go on from there.
        ``progress=True`` shows a progress bar (tqdm if installed, else a line on stderr).
        ``trajectory=PATH`` writes an H5MD file (docs/h5md.md; replaced if present) with a
        frame at each of these instants, as ``hypergas run --trajectory-every`` does.
        """
        until = _time_argument("until", until)
        t0 = self.time
        if not until >= t0:
            raise ValueError(f"until must be >= the engine time {t0:.17g}, got {until!r}")
        if until > t0:  # the command's range of --until (at most 1e12)
            _hypergas.check_option(self._kind, "until", until)
        observers = tuple(observers)
        for o in observers:
            if not isinstance(o, _hypergas.Observer):
                raise TypeError("observers must be MomentsRecorder, VacfRecorder, "
                                "TransportRecorder, HelfandRecorder or StructureRecorder "
                                "objects, "
                                f"got {type(o).__name__}")
        if callback is not None and not callable(callback):
            raise TypeError(f"callback must be callable, got {type(callback).__name__}")
        writer = None
        if trajectory is not None and getattr(self, "_shear_rate", 0.0) != 0.0:
            raise ValueError("trajectory= cannot be combined with shear_rate in EDMD: an H5MD "
                             "box is periodic, without the Lees-Edwards offset that the "
                             "sheared images need")
        if trajectory is not None:
            if not hasattr(_hypergas, "TrajectoryRecorder"):
                raise RuntimeError("trajectory= needs a hypergas built with HDF5 (libhdf5-dev)")
            lanes = self._kind == "dsmc" and getattr(self, "scheme", "exact") == "lanes"
            writer = _hypergas.TrajectoryRecorder(
                os.fspath(trajectory), ids=not lanes,
                parameters=[("engine", self._kind), ("dim", str(self.dim)),
                            ("n", str(self.n)), ("seed", str(getattr(self, "seed", "")))])
            observers = observers + (writer,)
        sampling = bool(observers) or callback is not None
        if every is not None:
            every = _time_argument("every", every)
            _hypergas.check_option(self._kind, "every", every)
        # The command's sampling instants (hypergas/schedule.hpp): evenly spaced, the last
        # at until.
        schedule = _hypergas.Schedule(t0, until, 0.0 if every is None else every)
        bar = Progress(t0, until, f"{self._kind} D={self.dim}") if progress else None
        try:
            if sampling:
                for k in range(schedule.rows):
                    self._h.advance(schedule.time(k), bar)
                    if self._observed_at != self.time:
                        for o in observers:
                            self._h.observe(o)
                        if callback is not None:
                            callback(self)
                        self._observed_at = self.time
                    elif writer is not None and writer.frames == 0:
                        self._h.observe(writer)  # the file starts at the call's instant
            self._h.advance(until, bar)
        finally:
            if bar is not None:
                bar.close(self.time)
            if writer is not None and writer.frames > 0:
                writer.close()
        return self

    def observe(self, *observers):
        """Feeds the current state to each recorder (as run's observers do)."""
        for o in observers:
            self._h.observe(o)
        self._observed_at = self.time

    # ---- state --------------------------------------------------------------------
    @property
    def dim(self):
        """The dimension D."""
        return self._h.dim

    @property
    def n(self):
        """The number of particles."""
        return self._h.n

    @property
    def time(self):
        """Engine time (DSMC: mean collision times; EDMD: sigma sqrt(m/kT))."""
        return self._h.time

    @property
    def collisions(self):
        """Accepted collisions so far."""
        return self._h.collisions

    @property
    def velocities(self):
        """Read-only (n, dim) float64 view of the engine's velocities (no copy).

        Rows are particles in the engine's memory order (see EDMD.ids); the view follows
        the engine as it runs and keeps it alive. Change velocities by building a new
        engine: the engines keep bounds and sums that a write would invalidate.
        """
        return self._h.velocities

    @property
    def species(self):
        """Read-only uint8 view of each particle's species (0, 1), or None (one species)."""
        return self._h.species

    @property
    def species_masses(self):
        """Mass of each species (species 0 has mass 1)."""
        return self._h.species_masses

    @property
    def masses(self):
        """Mass of each particle (a new array; masses are stored per species)."""
        s = self._h.species
        if s is None:
            return np.ones(self.n)
        return self._h.species_masses[s]

    @property
    def kinetic_energy(self):
        """Sum of m v^2 / 2 (energy units), summed in long double."""
        return self._h.kinetic_energy

    @property
    def momentum(self):
        """Sum of m v (a new array of length dim), summed in long double."""
        return self._h.momentum

    @property
    def bytes_per_particle(self):
        """Bytes of engine state per particle."""
        return self._h.bytes_per_particle

    def __repr__(self):
        return (f"<hypergas.{type(self).__name__} dim={self.dim} n={self.n} "
                f"time={self.time:.6g} collisions={self.collisions}>")


def _time_argument(name, value):
    if isinstance(value, (bool, str, bytes)) or not isinstance(value, (int, float, np.number)):
        raise TypeError(f"{name} must be a number, got {type(value).__name__}")
    v = float(value)
    if not math.isfinite(v):
        raise ValueError(f"{name} must be a finite time, got {value!r}")
    return v


class DSMC(_Engine):
    """The spatially homogeneous hard-sphere gas: the exact Kac/Boltzmann process.

    The arguments are the options of ``hypergas run --engine dsmc``, with its defaults and
    checks (listed below, from the command's option table), ``scheme`` ("exact", "ntc"
    or "lanes") among them. With ``scheme="lanes"`` each deal moves particles between rows
    of ``velocities``: row i is not the same particle across deals.

    Units: time in equilibrium mean collision times; mass of species 0 = 1; velocities in
    units where the initial kT is ``temperature``.
    """

    _kind = "dsmc"

    def __init__(self, *args, **kwargs):
        given = _given(DSMC, args, kwargs)
        super().__init__(_hypergas.make_dsmc(**given))
        self.seed = int(given.get("seed", _DEFAULTS["dsmc"]["seed"]))
        self.scheme = str(given.get("scheme", _DEFAULTS["dsmc"]["scheme"]))

    @classmethod
    def from_velocities(cls, velocities, *, species=None, **kwargs):
        """A DSMC gas that starts from the given velocities (copied), shape (n, dim).

        ``species`` (0 or 1 per particle) with ``mass_ratio`` (the mass of species 1; species
        0 has mass 1) gives a two-mass gas. The total momentum must be zero: the time unit,
        the equilibrium mean collision time, is defined in the centre-of-mass frame, so
        subtract the mass-weighted mean velocity first. With the velocities and the seed of
        another DSMC engine at t = 0, the trajectory is that engine's, bit for bit. The other
        keyword arguments are the constructor's, less those that the velocities fix (dim,
        n) or that describe an initial state (init, fraction, temperature).
        """
        self = cls.__new__(cls)
        bound = _bind(DSMC.from_velocities.__func__.__signature__, None, velocities, **kwargs)
        given = {k: v for k, v in bound.arguments.items()
                 if k not in ("cls", "velocities") and v is not None}
        _Engine.__init__(self, _hypergas.make_dsmc_from(velocities, species, **given))
        self.seed = int(given.get("seed", _DEFAULTS["dsmc"]["seed"]))
        self.scheme = str(given.get("scheme", _DEFAULTS["dsmc"]["scheme"]))
        return self

    @property
    def model(self):
        """The collision model's name."""
        return _hypergas.model(self._h)

    @property
    def threads(self):
        """Threads the one system runs on (settable; the trajectory does not change)."""
        return _hypergas.threads(self._h)

    @threads.setter
    def threads(self, t):
        _hypergas.set_threads(self._h, t)

    @property
    def candidates(self):
        """Candidate pairs tested so far (collisions / candidates: the acceptance)."""
        return _hypergas.candidates(self._h)

    @property
    def temperature(self):
        """Kinetic temperature 2 E_kin / (D n) of the true velocities, energy units.

        A freely cooling granular gas (``restitution`` < 1, no drive) stores scaled
        velocities (see ``log_velocity_scale``): this is the temperature of the gas, not
        of the stored velocities.
        """
        scale = math.exp(2.0 * self.log_velocity_scale)
        return 2.0 * self.kinetic_energy / (self.dim * self.n) * scale

    # ---- granular gas -------------------------------------------------------------
    @property
    def restitution(self):
        """Coefficient of normal restitution alpha (1: elastic)."""
        return _hypergas.dsmc_granular(self._h)["restitution"]

    @property
    def real_time(self):
        """Time in mean collision times at the initial temperature.

        Equals ``time`` except in a freely cooling granular gas (``restitution`` < 1, no
        drive), whose ``time`` counts mean collision times at the current temperature, so
        that it advances at a constant collision rate while the gas cools (Haff's law in
        ``real_time``: T = T0 / (1 + real_time / t0)^2).
        """
        return _hypergas.dsmc_granular(self._h)["real_time"]

    @property
    def log_velocity_scale(self):
        """ln of the factor from the stored to the true velocities.

        A freely cooling granular gas is kept at its initial temperature in scaled
        velocities: the true velocities are ``velocities * exp(log_velocity_scale)``, and
        ``kinetic_energy`` and ``momentum`` are those of the stored ones. 0 otherwise.
        """
        return _hypergas.dsmc_granular(self._h)["log_velocity_scale"]

    @property
    def kicks(self):
        """White-noise kicks so far (``drive="white-noise"``)."""
        return _hypergas.dsmc_granular(self._h)["kicks"]


class EDMD(_Engine):
    """Event-driven molecular dynamics of hard spheres in a periodic box.

    The arguments are the options of ``hypergas run --engine edmd``, with its defaults and
    checks (listed below, from the command's option table). The particles start on a lattice
    at ``packing``, or at ``start_packing`` and then compressed (Lubachevsky-Stillinger) to
    ``packing``: a dense fluid rather than a crystal; a dense start takes a while. From
    packing 0.43 on in 3D the engine scans neighbour lists, below it cells.

    Units: sigma = m = kT = 1; time in sigma sqrt(m/kT); lengths in sigma.
    The engine renumbers particles by position from time to time (memory locality):
    ``velocities`` and ``positions`` rows are in memory order, ``ids[i]`` is the original
    number of row i (``np.argsort(ids)`` orders rows by particle).
    With ``shear_rate`` (per ideal-gas mean collision time) the box has Lees-Edwards
    sliding boundaries and ``velocities`` are those of the lab frame, the flow
    a (y - L/2) included; observers see the peculiar ones.
    """

    _kind = "edmd"

    def __init__(self, *args, **kwargs):
        given = _given(EDMD, args, kwargs)
        super().__init__(_hypergas.make_edmd(**given))
        self.seed = int(given.get("seed", _DEFAULTS["edmd"]["seed"]))
        self._shear_rate = float(given.get("shear_rate", 0.0))

    @classmethod
    def from_state(cls, positions, velocities, *, box, **kwargs):
        """An EDMD gas that starts from given positions and velocities (copied), shape
        (n, dim), in the periodic cube of side ``box`` (sigma units; positions are wrapped
        into [0, box)). The packing fraction follows: n spheres of diameter 1 in box^dim.
        No two spheres may overlap (ValueError naming the pair and by how much). Velocities
        are taken as given: a state written by hypergas (kT = 1) continues unchanged. The
        other keyword arguments are the constructor's, less those that the state fixes (dim,
        n, packing, start_packing) or that describe a generated start (init, ...).
        ``hypergas.read_trajectory(path).state(k)`` gives the arguments of a saved frame.
        """
        self = cls.__new__(cls)
        given = {k: v for k, v in kwargs.items() if v is not None}
        _Engine.__init__(self, _hypergas.make_edmd_from(positions, velocities, box, **given))
        self.seed = int(given.get("seed", _DEFAULTS["edmd"]["seed"]))
        self._shear_rate = float(given.get("shear_rate", 0.0))
        return self

    @property
    def positions(self):
        """Read-only (n, dim) view of the positions in the box [0, L)^dim (no copy).

        Reading it first brings every particle's stored record to the current time (the
        engine otherwise moves a particle only at its events); the trajectory then goes on
        the same up to round-off, not bit for bit. Rows in memory order (see ``ids``).
        """
        return _hypergas.positions(self._h)

    @property
    def ids(self):
        """Read-only uint32 view: the original particle number of each row."""
        return _hypergas.ids(self._h)

    def unwrapped_positions(self):
        """Positions without the periodic wrap, in original numbering (a new array)."""
        return _hypergas.unwrapped_positions(self._h)

    def _observable(self, name):
        return _hypergas.edmd_observables(self._h)[name]

    @property
    def box_side(self):
        """Side L of the periodic box (sigma)."""
        return self._observable("box_side")

    @property
    def packing(self):
        """Packing fraction (volume of the spheres / box volume)."""
        return self._observable("packing")

    @property
    def temperature(self):
        """Kinetic temperature sum m c^2 / (D n) (energy units) of the peculiar velocities:
        under shear c = v - a (y - L/2) e_x, the lab velocities less the streaming profile,
        as the command's kT and moments.csv; otherwise c = v."""
        return self._observable("temperature")

    @property
    def pressure_Z(self):
        """Reduced pressure Z = PV/(N kT) from the collision virial since the last
        reset_observables() (or the start); NaN while the gas is granular (restitution
        below 1) or sheared: neither is in equilibrium (the command's summary says the
        same)."""
        return self._observable("pressure_Z")

    @property
    def collision_rate(self):
        """Collisions per particle per unit time since the last reset_observables()."""
        return self._observable("collision_rate")

    @property
    def mean_free_time(self):
        """1 / collision_rate."""
        return self._observable("mean_free_time")

    def reset_observables(self):
        """Starts a new measurement window for pressure_Z and the collision rate."""
        _hypergas.reset_observables(self._h)

    # ---- granular gas -------------------------------------------------------------
    @property
    def restitution(self):
        """Coefficient of normal restitution in effect (1: elastic).

        Settable: the collisions from then on use the new value (in [0, 1]). Unlike
        ``hypergas run``, which equilibrates elastically for 20 % of --until and then
        quenches, an engine built with ``restitution`` < 1 is inelastic from the start;
        build it elastic, run it, and set ``restitution`` for the command's protocol.
        """
        return self._observable("restitution")

    @restitution.setter
    def restitution(self, alpha):
        _hypergas.set_restitution(self._h, alpha)

    @property
    def tc_time(self):
        """The TC model's time: a collision within it of either particle's previous one is
        elastic (``tc_time`` argument)."""
        return self._observable("tc_time")

    @property
    def tc_elastic_collisions(self):
        """Collisions that the TC rule made elastic so far."""
        return self._observable("tc_elastic_collisions")


# ---- the constructors' arguments, from the command's option table -----------------------
_POSITIONAL = ("dim", "n")  # may also be given by position: DSMC(3, 1000)
_TABLE = _hypergas.option_table()
_DEFAULTS = {e: {o["python"]: o["default"][e] for o in _TABLE if e in o["default"]}
             for e in ("dsmc", "edmd")}


def _engine_options(kind):
    return [o for o in _TABLE if kind in o["engines"] and o["use"] == "engine"]


def _signature(kind, extra=()):
    P = inspect.Parameter
    params = [P("self", P.POSITIONAL_OR_KEYWORD)]
    for o in _engine_options(kind):
        how = P.POSITIONAL_OR_KEYWORD if o["python"] in _POSITIONAL else P.KEYWORD_ONLY
        default = None if o["unset"] else o["default"][kind]
        params.append(P(o["python"], how, default=default))
    params += [P(name, P.KEYWORD_ONLY, default=d) for name, d in extra]
    return inspect.Signature(params)


def _doc(kind):
    lines = ["", "    Parameters (``hypergas run --engine %s``; None or not given: the default)"
             % kind, "    " + "-" * 40]
    for o in _engine_options(kind):
        default = o["unset"] or repr(o["default"][kind])
        lines.append(f"    {o['python']} : {o['type']}, default {default}")
        unit = f" [{o['unit']}]" if o["unit"] else ""
        lines.append(f"        {o['help']}{unit}")
    return "\n".join(lines) + "\n"


def _bind(signature, *args, **kwargs):
    """signature.bind(...), naming the nearest keyword when one is unknown (the command's
    "did you mean" rule)."""
    try:
        return signature.bind(*args, **kwargs)
    except TypeError as e:
        unknown = [k for k in kwargs if k not in signature.parameters]
        if not unknown:
            raise
        hint = _hypergas.did_you_mean(unknown[0], list(signature.parameters)[1:])
        raise TypeError(f"unexpected keyword argument '{unknown[0]}'{hint}") from None


def _given(cls, args, kwargs):
    """The arguments the caller gave (by position or keyword), as keywords."""
    bound = _bind(cls.__init__.__signature__, None, *args, **kwargs)
    return {k: v for k, v in bound.arguments.items()
            if k != "self" and v is not None}


DSMC.__init__.__signature__ = _signature("dsmc")
DSMC.from_velocities.__func__.__signature__ = inspect.Signature(
    [inspect.Parameter("cls", inspect.Parameter.POSITIONAL_OR_KEYWORD),
     inspect.Parameter("velocities", inspect.Parameter.POSITIONAL_OR_KEYWORD),
     inspect.Parameter("species", inspect.Parameter.KEYWORD_ONLY, default=None)]
    + [p.replace(kind=inspect.Parameter.KEYWORD_ONLY)
       for p in _signature("dsmc").parameters.values()
       if p.name in _hypergas.given_velocity_keywords()])
DSMC.__doc__ += _doc("dsmc")
EDMD.__init__.__signature__ = _signature("edmd")
EDMD.__doc__ += _doc("edmd")
