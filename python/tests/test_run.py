"""hypergas.run is `hypergas run`: the same options, the same outputs, the same files."""

import json
import subprocess

import pytest

import hypergas as hg

CASES = [
    # DSMC with the histograms of --histogram-every and a two-mass gas
    ("dsmc", dict(dim=3, n=3000, init="beams", until=3, every=0.25, seed=5,
                  histogram_every=1.0, mass_ratio=2.0, fraction=0.3)),
    # EDMD with the VACF's own grid and the structure outputs
    ("edmd", dict(dim=3, n=500, packing=0.3, until=4, seed=2, structure=True)),
]


def cli_args(engine, options):
    args = ["--engine", engine]
    for k, v in options.items():
        name = "--" + k.replace("_", "-")
        if v is True:
            args.append(name)
        else:
            args += [name, str(v)]
    return args


@pytest.mark.parametrize("engine,options", CASES)
def test_same_files_as_the_command(tmp_path, cli, engine, options):
    summary = hg.run(tmp_path / "py", engine=engine, **options)
    subprocess.run([cli, "run", *cli_args(engine, options), "--out", str(tmp_path / "cli")],
                   check=True, capture_output=True)
    py_files = sorted(p.name for p in (tmp_path / "py").iterdir())
    cli_files = sorted(p.name for p in (tmp_path / "cli").iterdir())
    assert py_files == cli_files
    for name in py_files:
        if name.endswith(".csv"):
            assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    with open(tmp_path / "cli" / "summary.json") as f:
        ref = json.load(f)
    process = {"wall_s", "collisions_per_s", "engine_s", "analysis_s", "output_s", "setup_s",
               "peak_rss_bytes_per_particle"}
    assert list(summary) == list(ref)
    for k in ref:
        if k not in process:
            assert summary[k] == ref[k], k


def test_bad_keywords_as_the_command(tmp_path):
    with pytest.raises(TypeError, match="did you mean 'restitution'"):
        hg.run(tmp_path / "a", restitutoin=0.5)
    with pytest.raises(ValueError, match="packing"):
        hg.run(tmp_path / "b", engine="edmd", packing=0.9)
    with pytest.raises(TypeError, match="unexpected keyword argument 'packing'"):
        hg.run(tmp_path / "c", engine="dsmc", packing=0.2)  # an EDMD option
    assert not (tmp_path / "a").exists() and not (tmp_path / "b").exists()


def test_version_is_the_commands(tmp_path, cli):
    """hypergas.__version__ is what `hypergas --version` prints and summary.json records."""
    line = subprocess.run([cli, "--version"], check=True, capture_output=True,
                          text=True).stdout.split()
    assert line[0] == "hypergas"
    assert hg.__version__ == line[1]
    summary = hg.run(tmp_path / "v", engine="dsmc", dim=3, n=200, until=0.5)
    assert summary["version"] == hg.__version__
