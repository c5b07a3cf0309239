"""Reading the tables of a ``hypergas sweep`` folder."""

import csv
import errno
import os

import numpy as np

_TABLES = {"cases": "sweep.csv", "groups": "groups.csv"}
_STRINGS = ("case", "group")          # ids with leading zeros: 0000, 0001, ...
_INTEGERS = ("replica", "replicas")


def _is_float(text):
    """Whether a field is a number (Python's float() also takes '1_0' and ' 1 ': not here)."""
    if "_" in text or text != text.strip():
        return False
    try:
        float(text)
    except ValueError:
        return False
    return True


def _column(name, values):
    if name in _STRINGS:
        return np.array(values, dtype=str)
    # unsigned 64-bit (the case's seed; a swept seed is `plan_seed`): may exceed 2^63,
    # exact only as an integer
    if name in ("seed", "plan_seed"):
        return np.array([int(v) for v in values], dtype=np.uint64)
    if name in _INTEGERS:
        return np.array([int(v) for v in values], dtype=np.int64)
    if all(v == "" or _is_float(v) for v in values):
        return np.array([float(v) if v else np.nan for v in values], dtype=np.float64)
    return np.array(values, dtype=str)


def read_sweep(path, table="cases", frame=None):
    """The table of a sweep folder written by ``hypergas sweep PLAN.toml --out DIR``.

    ``table="cases"`` reads DIR/sweep.csv (one row per finished case: ``case``, the swept
    options, ``replica``, ``seed`` and the summary fields); ``table="groups"`` reads
    DIR/groups.csv (one row per group of replicas: ``group``, the swept options,
    ``replicas``, the numeric fields with one value in each group's replicas, such as
    ``dim`` and ``n``, once under their own names, and ``<field>_mean``, ``<field>_se`` for
    each other numeric summary field), which
    exists only when the plan has ``[sweep] replicas`` > 1.

    A column whose non-empty fields are all numbers is float64 (an empty field is nan);
    ``case`` and ``group`` are strings (``"0003"``), ``seed`` is uint64, ``replica`` and
    ``replicas`` are int64; any other column is strings (an empty field is ``""``). Values
    are in the units of the cases' summary.json, unconverted.

    ``frame=None`` returns a pandas DataFrame when pandas imports and otherwise a dict
    {column name: numpy array} in header order; ``frame=True`` always a DataFrame,
    ``frame=False`` always the dict. Both hold the same values and dtypes.

    Example::

        >>> import hypergas
        >>> cases = hypergas.read_sweep("out")              # DataFrame, one row per case
        >>> cases[["case", "packing", "seed", "Z"]]
        >>> groups = hypergas.read_sweep("out", "groups", frame=False)
        >>> groups["Z_mean"], groups["Z_se"]                 # numpy float64 arrays
    """
    if table not in _TABLES:
        raise ValueError(f"read_sweep: table must be 'cases' (sweep.csv) or 'groups' "
                         f"(groups.csv), not {table!r}")
    if frame not in (None, True, False):
        raise ValueError(f"read_sweep: frame must be None, True or False, not {frame!r}")
    folder = os.fspath(path)
    file = os.path.join(folder, _TABLES[table])
    if not os.path.isdir(folder):
        raise FileNotFoundError(errno.ENOENT, "read_sweep: no sweep folder (expected the DIR "
                                "of `hypergas sweep PLAN.toml --out DIR`)", folder)
    if not os.path.isfile(file):
        why = ("written only when the plan has [sweep] replicas > 1" if table == "groups"
               else "written by `hypergas sweep PLAN.toml --out DIR` once a case finishes")
        raise FileNotFoundError(errno.ENOENT, f"read_sweep: no {_TABLES[table]} in the "
                                f"folder ({why})", file)
    with open(file, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"read_sweep: {file} is empty (no header)")
    header, rows = rows[0], rows[1:]
    if len(set(header)) != len(header):
        raise ValueError(f"read_sweep: {file}: repeated column names in {header}")
    for k, row in enumerate(rows):
        if len(row) != len(header):
            raise ValueError(f"read_sweep: {file} row {k + 1}: {len(row)} fields, the header "
                             f"has {len(header)}")
    table_dict = {name: _column(name, [row[j] for row in rows])
                  for j, name in enumerate(header)}
    if frame is False:
        return table_dict
    try:
        import pandas
    except ImportError:
        if frame:
            raise ImportError("read_sweep(frame=True) needs pandas; frame=False returns a "
                              "dict of numpy arrays") from None
        return table_dict
    return pandas.DataFrame(table_dict)
