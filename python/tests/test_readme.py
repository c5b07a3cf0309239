"""The README's Python example runs as written and does what its comments say."""

import pathlib
import re

import numpy as np

import hypergas as hg


def test_readme_python_block_runs():
    readme = pathlib.Path(__file__).resolve().parents[2] / "README.md"
    blocks = re.findall(r"```python\n(.*?)```", readme.read_text(), re.S)
    assert blocks, "README.md has no python block"
    scope = {}
    exec(compile(blocks[0], "README.md", "exec"), scope)
    g, rec, v, a, md = (scope[k] for k in ("g", "rec", "v", "a", "md"))
    assert isinstance(g, hg.DSMC) and g.time == 10.0
    assert v.shape == (g.n, 3) and not v.flags.writeable
    assert len(rec.column("time")) == 51  # every 0.2 from 0 to 10
    assert isinstance(a, hg.Analysis) and np.isfinite(a.kurtosis_x)
    assert isinstance(md, hg.EDMD) and md.time == 15.0
    # Z of the equilibrium fluid, not of the melting lattice: Carnahan-Starling within 0.6 %.
    # Five seeds gave 3.2691 +- 0.0031 (sd of one run; 0.2 % above CS), the start's
    # transient [0, 5] alone 3.230 (1.0 % below), so the margin is 4 sd from the measured
    # mean (false failure ~1e-5) and the transient fails it.
    eta = 0.2618
    cs = (1 + eta + eta**2 - eta**3) / (1 - eta) ** 3
    assert abs(md.pressure_Z / cs - 1) < 0.006
    # the figure the README's comment quotes
    assert f"pressure_Z: {md.pressure_Z:.3f} over t in [5, 15]" in blocks[0]


def test_example_07_table_is_what_relax_py_prints(tmp_path):
    """examples/07-python's README table is what relax.py prints (the seed fixes it)."""
    import subprocess
    import sys
    root = pathlib.Path(__file__).resolve().parents[2]
    text = (root / "examples" / "07-python" / "README.md").read_text()
    quoted = re.search(r"## Results.*?```\n(.*?)```", text, re.S).group(1).splitlines()
    rows = [l for l in quoted if l.strip()[:1].isdigit()]
    assert len(rows) == 6
    run = subprocess.run([sys.executable, str(root / "examples" / "07-python" / "relax.py"),
                          "--out", str(tmp_path)], capture_output=True, text=True, check=True,
                         cwd=tmp_path)
    printed = [l for l in run.stdout.splitlines() if l.strip()[:1].isdigit()]
    assert [r.split() for r in rows] == [p.split() for p in printed]


def test_readme_edmd_quick_commands_fill_their_lattice(cli, tmp_path):
    """Every EDMD run among the README's quick commands starts on a full lattice: the
    command says nothing of vacancies (N = sites: M^D sites in D <= 2, M^D / 2 for even M in
    D >= 3)."""
    import subprocess
    root = pathlib.Path(__file__).resolve().parents[2]
    text = (root / "README.md").read_text()
    blocks = re.findall(r"<!-- quick -->\n```sh\n(.*?)```", text, re.S)
    runs = [l for b in blocks for l in b.splitlines() if "--engine edmd" in l and " run " in l]
    assert runs, "no EDMD quick command"
    for line in runs:
        args = line.split("#")[0].split()
        dim, n = int(args[args.index("--dim") + 1]), int(args[args.index("--n") + 1])
        step = 2 if dim >= 3 else 1
        m = step
        while (m**dim // (2 if dim >= 3 else 1)) < n:
            m += step
        assert m**dim // (2 if dim >= 3 else 1) == n, line
        # and the command agrees: a short run of the same gas prints no vacancy note
        short = [cli, "run", "--engine", "edmd", "--dim", str(dim), "--n", str(n),
                 "--packing", args[args.index("--packing") + 1], "--until", "0.1",
                 "--out", str(tmp_path / f"d{dim}")]
        r = subprocess.run(short, capture_output=True, text=True, check=True)
        assert "vacancies" not in r.stderr, line


def test_example_08_states_its_tagged_particles():
    """examples/08-transport's README gives the tagged count main.cpp sets and the default
    of analysis::TransportSettings (that of `run --transport` for DSMC)."""
    root = pathlib.Path(__file__).resolve().parents[2]
    main = (root / "examples" / "08-transport" / "main.cpp").read_text()
    text = " ".join((root / "examples" / "08-transport" / "README.md").read_text().split())
    settings = (root / "analysis" / "include" / "hypergas" / "analysis" /
                "transport_recorder.hpp").read_text()
    tagged = int(re.search(r"ts\.tagged = (\d+);", main).group(1))
    default = int(re.search(r"int tagged = (\d+);", settings).group(1))
    assert f"displacements of {tagged} tagged particles" in text
    if tagged != default:
        assert f"default to {default}" in text
