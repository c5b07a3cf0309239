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
    assert isinstance(md, hg.EDMD) and md.time == 5.0 and md.pressure_Z > 1.0
