"""hypergas.run: ``hypergas run`` from Python, the same files from the same code."""

import json as _json
import os as _os

from . import _hypergas


def run(out, engine="dsmc", **options):
    """Run one simulation as ``hypergas run --engine ENGINE --out OUT ...`` does and return
    its summary.json as a dict.

    The keyword arguments are the command's run options in Python spelling (``dim``, ``n``,
    ``until``, ``every``, ``mass_ratio``, ``transport``, ``histogram_every``,
    ``checkpoint_every``, ...: ``hypergas run --help`` gives each with its unit and
    default; ``_hypergas.run_keywords(engine)`` lists them), checked by the same table: a bad value raises ValueError with the command's
    message, an unknown keyword TypeError naming the nearest one. The run goes through the
    command's own engine runs and outputs, so ``out`` receives the same files, bit for bit,
    as the command writes for the same options (moments.csv, speed_histogram.csv,
    summary.json, the PNGs and whatever the options add). A folder holding files hypergas
    did not write is refused. Runs without a progress bar, and Ctrl-C takes effect when
    the run has ended.
    """
    out = _os.fspath(out)
    _hypergas.run_command(out, engine, **options)
    with open(_os.path.join(out, "summary.json"), encoding="utf-8") as f:
        return _json.load(f)
