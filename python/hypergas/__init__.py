"""hypergas: kinetic theory of hard-sphere gases in D = 1..6, from Python.

Two engines, the same as the ``hypergas`` command's:

* :class:`DSMC` -- the exact Kac/Boltzmann process in velocity space (hard spheres,
  Maxwell molecules, variable hard spheres). Time in equilibrium mean collision times.
* :class:`EDMD` -- event-driven molecular dynamics of hard spheres in a periodic box.
  Units sigma = m = kT = 1; time in sigma sqrt(m/kT).

Both take the command's options as keyword arguments (``n``, ``dim``, ``seed``, ...), are
checked by the same code (a bad value raises ValueError with the command's message) and
advance with ``run(until, every=..., callback=..., observers=..., progress=...)``.
``engine.velocities`` (and, for EDMD, ``engine.positions``) are read-only numpy views of the
engine's memory, not copies.

Analysis: :func:`analyse` (moments, kurtosis, speed histogram against the D-dimensional
Maxwell-Boltzmann density, L1/KL distances, KS and chi-square p-values: one row of the
command's moments.csv), :class:`MomentsRecorder` and :class:`VacfRecorder` (the command's
recorders, fed by ``run(observers=...)``), :func:`vacf`, :func:`msd`, :func:`maxwell_pdf`,
:func:`maxwell_cdf` and :func:`report` (error against run time).

Runs with files: :func:`run` is ``hypergas run`` (the same options, outputs and files;
``trajectory_every=`` writes trajectory.h5, ``init_file=`` starts from one).
:func:`read_trajectory` reads an H5MD file; :meth:`EDMD.from_state` starts from a frame.

Sweeps: :func:`read_sweep` reads the tables (sweep.csv, groups.csv) of a folder written by
``hypergas sweep``.

``__version__`` is the version of the build, that of ``hypergas --version``.
"""

import os as _os
import sys as _sys

try:
    import numpy as _numpy  # noqa: F401
except ImportError:
    # Debian's python3-numpy (and python3-matplotlib) live in /usr/lib/python3/dist-packages,
    # which only /usr/bin/python3 searches. Another CPython of the same minor version (a
    # pyenv or a source build first on PATH) loads this extension and those packages alike.
    _debian = "/usr/lib/python3/dist-packages"
    if _os.path.isdir(_debian) and _debian not in _sys.path:
        _sys.path.append(_debian)
    import numpy as _numpy  # noqa: F401

from ._engines import DSMC, EDMD
from ._analysis import (Analysis, Report, SpeedHistogram, analyse, maxwell_cdf, maxwell_pdf, msd,
                        report, vacf, MomentsRecorder, VacfRecorder,
                        TransportRecorder, HelfandRecorder, StructureRecorder,
                        PressureTensorRecorder)
from ._sweep import read_sweep
from ._run import run
from ._trajectory import Trajectory, read_trajectory
from . import _hypergas

__version__ = _hypergas.version  # that of `hypergas --version` and summary.json's "version"
models = tuple(_hypergas.model_names())
initial_states = tuple(_hypergas.initial_state_names())
schemes = tuple(_hypergas.scheme_names())
jamming_packing = _hypergas.jamming_packing

__all__ = ["DSMC", "EDMD", "Analysis", "Report", "SpeedHistogram", "analyse", "maxwell_pdf",
           "maxwell_cdf", "vacf", "msd", "report", "MomentsRecorder", "VacfRecorder",
           "TransportRecorder", "HelfandRecorder", "StructureRecorder", "PressureTensorRecorder",
           "read_sweep", "run", "read_trajectory", "Trajectory", "models", "initial_states", "schemes", "jamming_packing"]
