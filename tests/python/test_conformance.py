# dspbr.conformance (python/dspbr/conformance.py) with `dspbr conformance generate` and `check`: the
# reference through the Python module passes; results from the published tables fail where they read
# them; a bad value raises ValueError naming the vector.
import json
import os
import re
import shlex
import subprocess
import sys

import pytest

import dspbr.conformance as dc
from conftest import SOURCE_DIR, dspbr_exe, run_cli


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


def test_tables_option_judges_against_those_tables(vectors, tmp_path):
    # The published tables' results fail as written (test above) and pass against the reference
    # reading the same tables; the report says which tables; an unknown set is refused up front.
    path = tmp_path / "results.json"
    dc.write_results(dc.run(vectors, lambda v: dc.reference_eval(v, tables="published")), path)
    code, out, err = run_cli("conformance", "check", vectors, path, "--no-html", "--tables", "published",
                             "--out", tmp_path / "report")
    assert code == 0, out + err
    assert "with the published tables" in err
    report = json.loads((tmp_path / "report" / "report.json").read_text())
    assert report["provenance"]["tables"] == "published"
    code, _, err = run_cli("conformance", "check", vectors, path, "--no-html", "--tables", "publishd",
                           "--out", tmp_path / "bad")
    assert code == 2 and err.startswith("dspbr: error: --tables:"), err
    assert not (tmp_path / "bad").exists()
    code, _, err = run_cli("conformance", "check", vectors, path, "--no-html", "--min-roughness", "1.5",
                           "--out", tmp_path / "bad")
    assert code == 2 and "--min-roughness" in err, err
    # The published tables' results with roughness clamped to 0.05 (what the library computes
    # for that representation) against the reference with both: recorded in the provenance.
    code, out, err = run_cli("conformance", "check", vectors, path, "--no-html", "--tables", "published",
                             "--min-roughness", "0.05", "--out", tmp_path / "clamped")
    report = json.loads((tmp_path / "clamped" / "report.json").read_text())
    assert report["provenance"]["min_roughness"] == 0.05 and report["provenance"]["tables"] == "published"
    assert "roughness at least 0.05" in err


def test_run_batched_is_run_with_one_call_per_material(vectors):
    # The reference vectorised (dspbr.Bsdf takes (n, 3) arrays) through run_batched gives the same
    # results as reference_eval through run, with one call per material instead of one per vector.
    import numpy as np
    from dspbr import Bsdf
    calls = []

    def batch(material, options, v, l):
        calls.append(len(v))
        opts = options or {}
        kwargs = {"sheen": opts.get("sheen", "main")}
        if "position" in opts:
            kwargs["position"], kwargs["object_normal"] = tuple(opts["position"]), tuple(opts["object_normal"])
        b = Bsdf(material, **kwargs)
        return {"f_cos": b.eval(v, l) * np.abs(l[:, 2:3]), "pdf": b.pdf(v, l)}

    batched = dc.run_batched(vectors, batch)
    assert batched == dc.run(vectors, dc.reference_eval)
    assert sum(calls) == len(batched["results"]) and len(calls) < len(batched["results"]) / 3
    with pytest.raises(ValueError, match=r"vector 'plain_metal/gold-r10/00': f_cos of a batch of \d+ must have shape"):
        dc.run_batched(vectors, lambda m, o, v, l: np.zeros((len(v), 2)))
    with pytest.raises(ValueError, match=r"unknown key 'pfd' \(did you mean 'pdf'\?\)"):
        dc.run_batched(vectors, lambda m, o, v, l: {"f_cos": np.zeros((len(v), 3)), "pfd": np.zeros(len(v))})
    nan_pdf = dc.run_batched(vectors, lambda m, o, v, l: {"f_cos": np.zeros((len(v), 3)), "pdf": np.full(len(v), np.nan)})
    assert all("pdf" not in r for r in nan_pdf["results"])  # NaN: not supplied


def test_bad_values_name_the_vector(vectors):
    with pytest.raises(ValueError, match=r"vector 'plain_metal/gold-r10/00': f_cos\[1\] must be a finite number, got nan"):
        dc.run(vectors, lambda v: [0.0, float("nan"), 0.0])
    with pytest.raises(ValueError, match="f_cos must be 3 finite numbers"):
        dc.run(vectors, lambda v: [1, 2])


def test_demo_summary_block(tmp_path):
    # The machinery of scripts/conformance_demo.sh on a small set: the reference with each demo table
    # set, its report, and the summary written between the markers of a copy of the doc.
    demo = tmp_path / "demo"
    code, _, err = run_cli("conformance", "generate", "--directions", 2, "--no-albedo", "--out", demo / "vectors")
    assert code == 0, err
    vectors = demo / "vectors" / "vectors.json"
    expected = {"renderer": 0, "published": 1, "fits": None, "uncompensated": 1}
    for impl, status in expected.items():
        code, _, err = run_cli("conformance", "reference", vectors, "--tables", impl, "--out", demo / f"results-{impl}.json")
        assert code == 0, err
        code, out, err = run_cli("conformance", "check", vectors, demo / f"results-{impl}.json", "--no-html",
                                 "--out", demo / f"report-{impl}")
        assert code in (0, 1) and (status is None or code == status), (impl, out, err)
    doc = tmp_path / "doc.md"
    doc.write_text("before\n<!-- conformance-demo:begin -->\nold\n<!-- conformance-demo:end -->\nafter\n")
    subprocess.run([sys.executable, os.path.join(SOURCE_DIR, "scripts", "report", "conformance_demo_summary.py"),
                    str(demo), str(doc)], check=True)
    text = doc.read_text()
    assert text.startswith("before\n<!-- conformance-demo:begin -->\n**The reference with the published tables")
    assert "\nold\n" not in text and text.endswith("<!-- conformance-demo:end -->\nafter\n")
    # Without compensation the rough plain metal fails; every mirror passes (no tables there).
    block = text.split("Without energy compensation")[1]
    assert "| plain_metal |" in block and "| r = 0 | 0 / " in block


def test_documented_commands_run(tmp_path):
    # Every `build/...` line of docs/conformance.md's code blocks, in order, in a fresh folder with
    # build/, data/ and examples/ linked (the vector sets with 2 directions per material, to stay
    # cheap; `conformance run` skips, 77, without a Vulkan device).
    doc = open(os.path.join(SOURCE_DIR, "docs", "conformance.md"), encoding="utf-8").read()
    commands = re.findall(r"^    (build/\S+ .*)$", doc, flags=re.M)
    assert len(commands) >= 6
    os.symlink(os.path.dirname(os.path.abspath(dspbr_exe())), tmp_path / "build")
    os.symlink(os.path.join(SOURCE_DIR, "data"), tmp_path / "data")
    os.symlink(os.path.join(SOURCE_DIR, "examples"), tmp_path / "examples")
    for command in commands:
        args = shlex.split(command)
        if args[1:3] == ["conformance", "generate"] and "--directions" not in args:
            args += ["--directions", "2"]
        p = subprocess.run(args, cwd=tmp_path, capture_output=True, text=True)
        if p.returncode == 77 and args[1:3] == ["conformance", "run"]:
            continue
        assert p.returncode == 0, (command, p.stdout, p.stderr)


def test_the_report_writes_nothing_outside_its_folder(vectors, tmp_path):
    # Without a $HOME folder (found by a fresh tester: matplotlib created $HOME/.cache and
    # $HOME/.config, and $HOME itself) the report keeps matplotlib's caches in its staging folder
    # and removes them; the report is complete.
    path = tmp_path / "results.json"
    dc.write_results(dc.run(vectors, dc.reference_eval), path)
    env = dict(os.environ, HOME=str(tmp_path / "nohome"))
    p = subprocess.run([dspbr_exe(), "conformance", "check", vectors, str(path), "--out", str(tmp_path / "report")],
                       capture_output=True, text=True, env=env)
    assert p.returncode == 0, p.stdout + p.stderr
    assert not (tmp_path / "nohome").exists()
    assert (tmp_path / "report" / "index.html").is_file()
    assert not (tmp_path / "report" / ".matplotlib").exists()


def test_outputs_its_own_tools_would_refuse_are_refused(vectors, tmp_path):
    # Found by this stop's third fresh tester: `reference --out` naming the vector file replaced it
    # with results, and `generate --directions 200` wrote a 22.8 MB vectors.json that check, reference
    # and load refuse (16 MB limit).
    copy = tmp_path / "v.json"
    copy.write_bytes(open(vectors, "rb").read())
    code, _, err = run_cli("conformance", "reference", copy, "--out", copy)
    assert code == 2 and "is the vector file itself" in err, err
    assert copy.read_bytes() == open(vectors, "rb").read()
    code, _, err = run_cli("conformance", "generate", "--directions", 200, "--no-albedo", "--out", tmp_path / "big")
    assert code == 2 and "larger than the limit of 16.0 MB" in err, err
    assert not (tmp_path / "big").exists()


def check_with_groups(tmp_path, group_of):
    # The built-in vectors (one direction pair, no albedo, no scenes) regrouped by group_of(i), the
    # reference's own results and the check of those: (exit status, stdout, stderr); edited.json and
    # r.json stay in tmp_path, the report in tmp_path/report.
    code, _, err = run_cli("conformance", "generate", "--directions", 1, "--no-albedo", "--no-scenes", "--out",
                           tmp_path / "v")
    assert code == 0, err
    doc = json.loads((tmp_path / "v" / "vectors.json").read_text())
    for i, v in enumerate(doc["vectors"]):
        v["group"] = group_of(i)
    (tmp_path / "edited.json").write_text(json.dumps(doc))
    code, _, err = run_cli("conformance", "reference", tmp_path / "edited.json", "--out", tmp_path / "r.json")
    assert code == 0, err
    return run_cli("conformance", "check", tmp_path / "edited.json", tmp_path / "r.json", "--out", tmp_path / "report")


def test_report_labels_escape_control_characters(tmp_path):
    # A group named with an escape sequence: the report is written and nothing raw reaches stderr
    # (matplotlib warned about the missing glyph, quoting it; the tenth fresh tester's pass).
    code, out, err = check_with_groups(tmp_path, lambda i: "x\x1b[31mred\x07" if i % 2 else "plain")
    assert code == 0, (out, err)
    assert (tmp_path / "report" / "plots" / "ratio_by_group.png").is_file()
    assert "\x1b" not in err and "\x07" not in err and "Warning" not in err, err
    page = (tmp_path / "report" / "index.html").read_text(encoding="utf-8")
    assert "\x1b" not in page and "\x07" not in page and "x\\x1b[31mred\\x07" in page


def test_report_of_many_groups_and_long_names(tmp_path):
    # A vector file with 60 groups, one named in 5000 characters, one "$\frac{$": the HTML report's
    # plots show the 40 worst groups with shortened, escaped labels (the plotting library refused the figure and the whole report
    # was lost; the eighth fresh tester's pass).
    code, out, err = check_with_groups(
        tmp_path, lambda i: "a" * 5000 if i == 0 else ("$\\frac{$" if i == 1 else f"group-{i % 60}"))
    assert code == 0, (out, err)
    for name in ("index.html", "plots/ratio_by_group.png", "plots/relative_error_by_group.png"):
        assert (tmp_path / "report" / name).is_file(), name
    # A group named "$\frac{$" (matplotlib's mathematics) and results without any f cos (a pdf
    # alone): the report is written (the ninth fresh tester's pass: tracebacks, the report lost).
    results = json.loads((tmp_path / "r.json").read_text())["results"]
    (tmp_path / "pdf.json").write_text(json.dumps({"results": [{"id": r["id"], "pdf": r["pdf"]} for r in results]}))
    code, out, err = run_cli("conformance", "check", tmp_path / "edited.json", tmp_path / "pdf.json", "--out",
                             tmp_path / "report-pdf")
    assert code == 0, (out, err)
    assert (tmp_path / "report-pdf" / "index.html").is_file()
