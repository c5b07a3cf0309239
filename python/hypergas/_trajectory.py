"""hypergas.read_trajectory: an H5MD file (trajectory.h5 of ``--trajectory-every`` or any
H5MD file with velocities) as numpy arrays. Needs h5py (Debian python3-h5py)."""

import numpy as _np


class Trajectory:
    """The frames of one H5MD particle group, read into numpy arrays (or, with
    ``lazy=True``, kept as h5py datasets read on access).

    Attributes: ``dim``, ``n``, ``time`` and ``step`` (one per frame), ``velocities``
    (frames, n, dim), and where the file has them ``positions`` (wrapped into the box),
    ``images`` (unwrapped = positions + images * box), ``box`` (the cube's side per frame),
    ``species``, ``mass``, ``ids``; ``observables`` maps each name to its (frames,) values;
    ``parameters`` the run's options as text (hypergas files). Units are hypergas's reduced
    ones (docs/h5md.md).
    """

    def __init__(self, path, group=None, lazy=False):
        try:
            import h5py
        except ImportError as e:  # pragma: no cover - h5py is a Debian package
            raise ImportError("read_trajectory needs h5py (Debian: python3-h5py)") from e
        self._file = h5py.File(path, "r")
        f = self._file
        if "particles" not in f or "h5md" not in f:
            f.close()
            raise ValueError(f"{path}: not an H5MD file (no /h5md or /particles group)")
        names = list(f["particles"])
        if group is None:
            group = "all" if "all" in names else (names[0] if len(names) == 1 else None)
        if group not in names:
            f.close()
            raise ValueError(f"{path}: name the particle group, one of {names}")
        g = f["particles"][group]
        take = (lambda d: d) if lazy else (lambda d: d[()])
        self.dim = int(g["box"].attrs["dimension"])
        vel = g["velocity"]
        self.velocities = take(vel["value"])
        self.time = take(vel["time"])
        self.step = take(vel["step"])
        self.n = int(vel["value"].shape[1])
        self.positions = take(g["position/value"]) if "position" in g else None
        self.images = take(g["image/value"]) if "image" in g else None
        self.box = None
        if "edges" in g["box"]:  # the cube's side: a vector or a D x D matrix, per frame or not
            e = g["box/edges"]
            per_frame = isinstance(e, h5py.Group)
            e = _np.asarray(e["value"][()] if per_frame else e[()])
            matrix = e.ndim == (3 if per_frame else 2)
            self.box = e[..., 0, 0] if matrix else e[..., 0]
        self.species = g["species"][()] if "species" in g else None
        self.mass = g["mass"][()] if "mass" in g else None
        self.ids = g["id"][()] if "id" in g else None
        self.observables = {}
        if "observables" in f:
            for k, v in f["observables"].items():
                self.observables[k] = take(v["value"]) if isinstance(v, h5py.Group) else v[()]
        self.parameters = {}
        if "parameters/hypergas" in f:
            for k, v in f["parameters/hypergas"].attrs.items():
                self.parameters[k] = v.decode() if isinstance(v, bytes) else str(v)
        if not lazy:
            self.close()

    def __len__(self):
        return len(self.time)

    def state(self, k=-1):
        """The keyword arguments of frame k for ``EDMD.from_state`` (positions,
        velocities, box) or ``DSMC.from_velocities`` (velocities, when the file has no
        positions)."""
        v = _np.asarray(self.velocities[k])
        if self.positions is None:
            return {"velocities": v}
        box = _np.atleast_1d(self.box)
        return {"positions": _np.asarray(self.positions[k]), "velocities": v,
                "box": float(box[k] if box.size > 1 else box[0])}

    def close(self):
        """Closes the file (lazy reads end here)."""
        if self._file is not None:
            self._file.close()
            self._file = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def read_trajectory(path, group=None, lazy=False):
    """Reads an H5MD trajectory: see :class:`Trajectory`. ``lazy=True`` keeps h5py datasets
    (read frame by frame on access; close() or a ``with`` block ends them)."""
    return Trajectory(path, group, lazy)
