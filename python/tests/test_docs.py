"""Every ```python block of docs/*.md and examples/*/README.md runs as written and makes what
its text says (README.md's block: test_readme.py).

A block that reads files is preceded by the ```sh block that makes them: when the fenced
block just before a python block is a sh block, the test runs it first with bash, in a
fresh folder laid out as the repository's root (`examples/` linked there, `hypergas` on
PATH and `build/sim/hypergas` both the built command). The python block is then executed
in that folder, and CHECKS[(file, k)] (the file's k-th python block) compares what it made
with the files, read by other means. A block without a check fails, as does a check
without its block."""

import csv
import json
import os
import pathlib
import re
import subprocess

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
FENCE = re.compile(r"^```(\w*)\n(.*?)^```[ \t]*$", re.S | re.M)
OPTIONAL = ("h5py", "MDAnalysis", "pandas", "matplotlib")  # a block importing one is skipped
                                                           # where it is not installed


def doc_files():
    return sorted(ROOT.glob("docs/*.md")) + sorted(ROOT.glob("examples/*/README.md"))


def python_blocks():
    """[(name, k, setup sh or None, python source)], name relative to the repository."""
    found = []
    for path in doc_files():
        fences = FENCE.findall(path.read_text())
        k = 0
        for i, (lang, body) in enumerate(fences):
            if lang != "python":
                continue
            setup = fences[i - 1][1] if i > 0 and fences[i - 1][0] == "sh" else None
            found.append((path.relative_to(ROOT).as_posix(), k, setup, body))
            k += 1
    return found


BLOCKS = python_blocks()


def run_setup(setup, where, cli):
    """The sh block's commands in `where`, as a user runs them from the repository root."""
    (where / "examples").symlink_to(ROOT / "examples")
    for link in (where / "bin" / "hypergas", where / "build" / "sim" / "hypergas"):
        link.parent.mkdir(parents=True)
        link.symlink_to(os.path.abspath(cli))
    env = dict(os.environ, PATH=f"{where / 'bin'}{os.pathsep}{os.environ.get('PATH', '')}")
    r = subprocess.run(["bash", "-euo", "pipefail", "-c", setup], cwd=where, env=env,
                       capture_output=True, text=True)
    assert r.returncode == 0, f"the sh block failed:\n{setup}\n{r.stderr}"


def h5md_mdanalysis(scope, where, stdout):
    import h5py
    path = where / "out" / "edmd3" / "trajectory.h5"
    with h5py.File(path, "r") as f:
        x = f["particles/all/position/value"][:]
        v = f["particles/all/velocity/value"][:]
        t = f["particles/all/position/time"][:]
        L = f["particles/all/box/edges/value"][0, 0, 0]
    summary = json.loads((where / "out" / "edmd3" / "summary.json").read_text())
    frames = summary["trajectory_frames"]
    assert x.shape == (frames, 108, 3)
    u = scope["u"]
    assert len(u.trajectory) == frames == 9 and u.atoms.n_atoms == 108
    # the comment's times, and h5py's
    assert np.allclose(scope["t"], np.arange(1, 5.25, 0.5), rtol=0, atol=1e-12)
    assert np.allclose(scope["t"], t, rtol=0, atol=1e-12)
    # MDAnalysis keeps coordinates in single precision
    assert scope["x"].shape == x.shape and scope["x"].dtype == np.float32
    assert np.allclose(scope["x"], x, rtol=1e-6, atol=1e-5 * L)
    assert np.all((scope["x"] >= 0) & (scope["x"] <= L))
    assert scope["v"].shape == v.shape and np.allclose(scope["v"], v, rtol=1e-6, atol=1e-6)
    assert np.allclose(scope["box"], [L, L, L, 90, 90, 90], rtol=1e-6)
    assert stdout == f"9 frames of 108 atoms, t = 1.0 .. 5.0, L = {L:.6f}\n"


def sweeps_read_sweep(scope, where, stdout):
    with open(where / "out" / "eos3d" / "sweep.csv") as f:
        rows = list(csv.DictReader(f))
    with open(where / "out" / "eos3d" / "groups.csv") as f:
        group_rows = list(csv.DictReader(f))
    assert len(rows) == 10 and len(group_rows) == 5  # 5 packings x 2 replicas
    cases, groups, arrays = scope["cases"], scope["groups"], scope["arrays"]
    try:
        import pandas
        assert isinstance(cases, pandas.DataFrame) and isinstance(groups, pandas.DataFrame)
        columns = list(cases.columns)
    except ImportError:
        assert isinstance(cases, dict)
        columns = list(cases)
    assert isinstance(arrays, dict) and list(arrays) == columns == list(rows[0])
    assert list(arrays["case"]) == [f"{i:04d}" for i in range(10)]
    assert np.allclose(arrays["packing"], np.repeat([0.05, 0.15, 0.25, 0.35, 0.45], 2))
    assert np.array_equal(arrays["Z"], [float(r["Z"]) for r in rows])
    assert np.array_equal(np.asarray(cases["Z"]), arrays["Z"])
    z = arrays["Z"].reshape(5, 2)
    assert np.allclose(np.asarray(groups["Z_mean"]), z.mean(1), rtol=1e-12)
    assert np.allclose(np.asarray(groups["Z_se"]), z.std(1, ddof=1) / np.sqrt(2), rtol=1e-9)


CHECKS = {
    ("docs/h5md.md", 0): h5md_mdanalysis,
    ("docs/sweeps.md", 0): sweeps_read_sweep,
}


def test_the_docs_have_their_python_blocks():
    """Each check has its block (a block that went away, or moved, is noticed)."""
    have = {(name, k) for name, k, _, _ in BLOCKS}
    assert set(CHECKS) <= have, f"checks without a block: {sorted(set(CHECKS) - have)}"


@pytest.mark.parametrize("name,k,setup,source", BLOCKS,
                         ids=[f"{name}#{k}" for name, k, _, _ in BLOCKS])
def test_python_block_runs_as_written(name, k, setup, source, cli, tmp_path, monkeypatch,
                                      capsys):
    check = CHECKS.get((name, k))
    assert check, f"{name}: python block {k} has no check in test_docs.py"
    for module in OPTIONAL:
        if re.search(rf"^\s*(import|from)\s+{module}\b", source, re.M):
            pytest.importorskip(module)
    if setup is not None:
        run_setup(setup, tmp_path, cli)
    monkeypatch.chdir(tmp_path)
    scope = {"__name__": "__main__"}
    exec(compile(source, f"{name} (python block {k})", "exec"), scope)
    check(scope, tmp_path, capsys.readouterr().out)
