# dspbr.conformance (python/dspbr/conformance.py) with `dspbr conformance generate` and `check`: the
# reference through the Python module passes; results from the published tables fail where they read
# them; a bad value raises ValueError naming the vector.
import json

import pytest

import dspbr.conformance as dc
from conftest import run_cli


@pytest.fixture(scope="module")
def vectors(tmp_path_factory):
    out = tmp_path_factory.mktemp("conformance") / "v"
    code, _, err = run_cli("conformance", "generate", "--directions", 2, "--no-albedo", "--out", out)
    assert code == 0, err
    return str(out / "vectors.json")


def check(vectors, results, tmp_path):
    path = tmp_path / "results.json"
    dc.write_results(results, path)
    code, out, err = run_cli("conformance", "check", vectors, path, "--no-html", "--out", tmp_path / "report")
    report = json.loads((tmp_path / "report" / "report.json").read_text()) if code in (0, 1) else None
    return code, report, out + err


def test_reference_passes(vectors, tmp_path):
    code, report, text = check(vectors, dc.run(vectors, dc.reference_eval), tmp_path)
    assert code == 0, text
    assert report["quantities"]["pdf"]["judged"] == report["summary"]["vectors"]


def test_published_tables_fail_where_tables_are_read(vectors, tmp_path):
    code, report, text = check(vectors, dc.run(vectors, lambda v: dc.reference_eval(v, tables="published")), tmp_path)
    assert code == 1, text
    groups = {g["name"]: g["verdict"] for g in report["groups"]}
    assert groups["plain_metal"] == "FAIL"  # the multiple-scattering term reads GGX_E
    # A vector without tables (the mirror metal: no multiple scattering, docs/bsdf.md) passes.
    mirror = [v for v in report["vectors"] if v["id"].startswith("metallic/metal-mirror/")]
    assert mirror and all(v["verdict"] == "PASS" for v in mirror)


def test_bad_values_name_the_vector(vectors):
    with pytest.raises(ValueError, match=r"vector 'plain_metal/gold-r10/00': f_cos must be 3 finite numbers"):
        dc.run(vectors, lambda v: [0.0, float("nan"), 0.0])
    with pytest.raises(ValueError, match="f_cos must be 3 finite numbers"):
        dc.run(vectors, lambda v: [1, 2])
