"""The option table from Python: the engines' signatures, defaults and docstrings are the
table's, the command lists the same options, and command and Python sample at the same
instants (hypergas/schedule.hpp) with identical moments.csv rows for any `every`."""

import inspect
import subprocess

import numpy as np
import pytest

import hypergas as hg
from hypergas import _hypergas

from conftest import run_cli

TABLE = _hypergas.option_table()


def engine_options(kind):
    return [o for o in TABLE if kind in o["engines"] and o["use"] == "engine"]


@pytest.mark.parametrize("cls,kind", [(hg.DSMC, "dsmc"), (hg.EDMD, "edmd")])
def test_signature_is_the_table(cls, kind):
    params = inspect.signature(cls).parameters
    assert list(params) == [o["python"] for o in engine_options(kind)]
    for o in engine_options(kind):
        p = params[o["python"]]
        assert p.default == (None if o["unset"] else o["default"][kind]), o["python"]
        assert o["python"] in cls.__doc__ and o["help"] in cls.__doc__
    # the defaults are the engines' own: a default engine has them
    e = cls(n=64) if kind == "dsmc" else cls(n=64, dim=2)
    assert e.seed == o_default(kind, "seed")


def o_default(kind, name):
    return next(o for o in TABLE if o["python"] == name)["default"][kind]


def test_from_velocities_takes_the_table_less_the_initial_state():
    params = inspect.signature(hg.DSMC.from_velocities).parameters
    expected = [o["python"] for o in engine_options("dsmc")
                if not o["initial_state"] and o["python"] not in ("dim", "n")]
    assert [p for p in params if p not in ("velocities", "species")] == expected


def test_unknown_and_other_engine_keywords():
    with pytest.raises(TypeError, match="packing"):
        hg.DSMC(n=64, packing=0.2)
    with pytest.raises(TypeError, match="threads"):
        hg.EDMD(n=64, threads=2)
    with pytest.raises(TypeError):
        hg.DSMC(n=64, no_such_option=1)


def test_the_command_lists_the_same_options(cli):
    out = subprocess.run([cli, "run", "--help"], capture_output=True, text=True,
                         check=True).stdout
    for o in TABLE:
        assert o["name"] + " " in out or o["name"] + "=" in out, o["name"]
        assert o["help"].split(":")[0] in out, o["name"]


def test_schedule_rule():
    for until in (1.0, 10.0):
        for every in (0.3, 0.25, 0.7):
            s = _hypergas.Schedule(0.0, until, every)
            k = max(1, round(until / every))
            assert s.intervals == k and s.rows == k + 1
            assert s.time(0) == 0.0 and s.time(k) == until
            assert s.every == until / k
    assert _hypergas.Schedule(0.0, 1.0, 0.0).rows == 51
    with pytest.raises(ValueError, match="at most 1e6"):
        _hypergas.Schedule(0.0, 1.0, 1e-7)


@pytest.mark.parametrize("until", [1, 10])
@pytest.mark.parametrize("every", [0.3, 0.25, 0.7])
def test_command_and_python_rows_agree(cli, tmp_path, until, every):
    _, rows, _ = run_cli(cli, tmp_path, "--engine", "dsmc", "--dim", 3, "--n", 4000,
                         "--until", until, "--every", every, "--seed", 3)
    g = hg.DSMC(dim=3, n=4000, seed=3)
    rec = hg.MomentsRecorder()
    g.run(until=until, every=every, observers=[rec])
    table = rec.table()
    k = max(1, round(until / every))
    assert len(rows) == len(table["time"]) == k + 1
    assert table["time"][-1] == until
    # 17 significant digits in the CSV: equal rows mean equal velocities at every instant
    for name in rec.columns:
        np.testing.assert_array_equal(table[name], [float(r[name]) for r in rows],
                                      err_msg=name)
