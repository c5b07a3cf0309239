"""read_sweep on sweep folders written here by hand (docs: the sweep folder format)."""

import numpy as np
import pytest

import hypergas as hg

SWEEP_CSV = (
    'case,packing,model,replica,seed,Z,note,verbose\r\n'
    '0000,0.1,hs,0,18446744073709551615,1.2345678901234567,"a, b",true\r\n'
    '0001,0.2,hs,1,7,,"say ""hi""",false\r\n'
    '0002,0.3,maxwell,0,9223372036854775808,-2.5e-07,,true\r\n'
)

GROUPS_CSV = (
    'group,packing,replicas,Z_mean,Z_se\n'
    '0000,0.1,2,1.5,0.25\n'
    '0001,0.2,1,3,\n'
)


@pytest.fixture
def sweep(tmp_path):
    (tmp_path / "sweep.csv").write_bytes(SWEEP_CSV.encode())
    (tmp_path / "groups.csv").write_text(GROUPS_CSV)
    return tmp_path


def check_cases(get):
    """get(name) -> numpy array of the column."""
    case = get("case")
    assert case.dtype.kind == "U" and case.tolist() == ["0000", "0001", "0002"]
    assert get("packing").dtype == np.float64
    assert get("packing").tolist() == [0.1, 0.2, 0.3]
    assert get("model").tolist() == ["hs", "hs", "maxwell"]
    assert get("replica").dtype == np.int64 and get("replica").tolist() == [0, 1, 0]
    seed = get("seed")
    assert seed.dtype == np.uint64
    assert seed.tolist() == [18446744073709551615, 7, 9223372036854775808]
    z = get("Z")
    assert z.dtype == np.float64
    assert z[0] == 1.2345678901234567 and np.isnan(z[1]) and z[2] == -2.5e-07
    assert get("note").tolist() == ["a, b", 'say "hi"', ""]
    assert get("verbose").tolist() == ["true", "false", "true"]


def test_cases_as_dict(sweep):
    t = hg.read_sweep(sweep, frame=False)
    assert type(t) is dict
    assert list(t) == ["case", "packing", "model", "replica", "seed", "Z", "note", "verbose"]
    assert all(isinstance(c, np.ndarray) and len(c) == 3 for c in t.values())
    assert t["model"].dtype.kind == "U" and t["note"].dtype.kind == "U"
    check_cases(t.__getitem__)


def test_groups_as_dict(sweep):
    g = hg.read_sweep(str(sweep), table="groups", frame=False)
    assert list(g) == ["group", "packing", "replicas", "Z_mean", "Z_se"]
    assert g["group"].tolist() == ["0000", "0001"] and g["group"].dtype.kind == "U"
    assert g["replicas"].dtype == np.int64 and g["replicas"].tolist() == [2, 1]
    assert g["Z_mean"].dtype == np.float64 and g["Z_mean"].tolist() == [1.5, 3.0]
    assert g["Z_se"][0] == 0.25 and np.isnan(g["Z_se"][1])


def test_header_only_table_has_empty_columns(tmp_path):
    (tmp_path / "sweep.csv").write_text("case,dt,replica,seed,kT\n")
    t = hg.read_sweep(tmp_path, frame=False)
    assert list(t) == ["case", "dt", "replica", "seed", "kT"]
    assert [len(c) for c in t.values()] == [0] * 5
    assert t["seed"].dtype == np.uint64 and t["kT"].dtype == np.float64


def test_cases_and_groups_as_frames(sweep):
    pd = pytest.importorskip("pandas")
    t = hg.read_sweep(sweep, frame=True)
    assert isinstance(t, pd.DataFrame)
    assert list(t.columns) == ["case", "packing", "model", "replica", "seed", "Z", "note",
                               "verbose"]
    assert t["seed"].dtype == np.uint64 and t["replica"].dtype == np.int64
    assert t["packing"].dtype == np.float64 and t["Z"].dtype == np.float64
    check_cases(lambda name: np.asarray(t[name].tolist()) if t[name].dtype == object
                else t[name].to_numpy())
    assert hg.read_sweep(sweep).equals(t)  # frame=None: a DataFrame when pandas imports
    g = hg.read_sweep(sweep, "groups", frame=True)
    assert g["group"].tolist() == ["0000", "0001"]
    assert g["replicas"].dtype == np.int64 and g["replicas"].tolist() == [2, 1]
    assert g["Z_mean"].tolist() == [1.5, 3.0] and np.isnan(g["Z_se"].iloc[1])


def test_frame_none_without_pandas_is_a_dict(sweep, monkeypatch):
    import builtins
    real_import = builtins.__import__

    def no_pandas(name, *args, **kwargs):
        if name == "pandas":
            raise ImportError("No module named 'pandas'")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_pandas)
    t = hg.read_sweep(sweep)
    assert type(t) is dict and t["seed"].tolist()[0] == 18446744073709551615
    with pytest.raises(ImportError, match="needs pandas"):
        hg.read_sweep(sweep, frame=True)


def test_errors(sweep, tmp_path):
    with pytest.raises(FileNotFoundError, match="no sweep folder") as e:
        hg.read_sweep(tmp_path / "absent")
    assert e.value.filename == str(tmp_path / "absent")
    (sweep / "groups.csv").unlink()
    with pytest.raises(FileNotFoundError, match=r"replicas > 1") as e:
        hg.read_sweep(sweep, "groups")
    assert e.value.filename == str(sweep / "groups.csv")
    (sweep / "sweep.csv").unlink()
    with pytest.raises(FileNotFoundError, match="no sweep.csv") as e:
        hg.read_sweep(sweep)
    assert e.value.filename == str(sweep / "sweep.csv")
    with pytest.raises(ValueError, match="'cases'.*'groups'.*'summary'"):
        hg.read_sweep(sweep, table="summary")
    (sweep / "sweep.csv").write_text("case,dt\n0000,0.1,9\n")
    with pytest.raises(ValueError, match="row 1: 3 fields, the header has 2"):
        hg.read_sweep(sweep, frame=False)


def test_a_sweep_of_the_command_reads_back(cli, tmp_path):
    """A sweep written by `hypergas sweep` reads into arrays that equal its cases' summaries."""
    import json
    import subprocess

    plan = tmp_path / "plan.toml"
    plan.write_text('engine = "dsmc"\ndim = 2\nuntil = 0.5\nseed = 5\n'
                    "[sweep]\nn = [300, 600]\nreplicas = 2\n")
    subprocess.run([cli, "sweep", str(plan), "--out", str(tmp_path / "s")], check=True,
                   capture_output=True)
    t = hg.read_sweep(tmp_path / "s", frame=False)
    assert t["case"].tolist() == ["0000", "0001", "0002", "0003"]
    assert t["n"].tolist() == [300.0, 300.0, 600.0, 600.0]
    assert t["replica"].tolist() == [0, 1, 0, 1]
    assert t["seed"].dtype == np.uint64
    for i, case in enumerate(t["case"]):
        summary = json.loads((tmp_path / "s" / "cases" / case / "summary.json").read_text())
        assert int(t["seed"][i]) == summary["seed"]
        assert t["kurtosis_x"][i] == summary["kurtosis_x"]  # verbatim: the same double
    g = hg.read_sweep(tmp_path / "s", table="groups", frame=False)
    assert g["replicas"].tolist() == [2, 2]
    np.testing.assert_allclose(g["kurtosis_x_mean"],
                               [t["kurtosis_x"][:2].mean(), t["kurtosis_x"][2:].mean()],
                               rtol=1e-14)
