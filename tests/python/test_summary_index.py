# The committed index of the full validation report (docs/validation/README.md) is written by
# scripts/report/summary_index.py: here from a quick run, its banner, run record and verdict table
# must be those of the report, its figures copied, and figures of an earlier index removed. The
# committed index must be the one of a full run, and every figure the docs show must exist.
import glob
import json
import os
import re
import subprocess
import sys

from conftest import SOURCE_DIR, dspbr_exe

SCRIPT = os.path.join(SOURCE_DIR, "scripts", "report", "summary_index.py")


def test_index_of_a_quick_report(tmp_path):
    out, dest = tmp_path / "report", tmp_path / "index"
    p = subprocess.run([dspbr_exe(), "validate", "--quick", "--no-html", "--out", str(out)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr[-2000:]
    dest.mkdir()
    (dest / "plots_stale.png").write_bytes(b"old")
    p = subprocess.run([sys.executable, SCRIPT, str(out), str(dest)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    rep = json.load(open(out / "data" / "report.json"))
    text = (dest / "README.md").read_text()
    assert rep["banner"].startswith("QUICK run") and f"**{rep['banner']}**" in text
    for key in ("git_commit",):
        assert rep["provenance"][key] in text
    assert rep["run"]["date_utc"] in text
    # The command relative to the checkout: the index is the same wherever the project sits.
    checkout = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(SCRIPT)))) + os.sep
    assert rep["run"]["command_line"].replace(checkout, "") in text
    assert checkout not in text
    for c in rep["summary"]:
        assert f"| {c['check']} | {c['passed']} | {c['failed']} | {c['waived']} | {c['not_judged']} | {c['total']} |" in text
    assert len(re.findall(r"^\| \S+ \(renderer\) \|", text, flags=re.M)) == len(rep["tables"]["tables"]) == 10
    assert not (dest / "plots_stale.png").exists()
    for name in re.findall(r"!\[[^\]]*\]\(([^)]+)\)", text):
        assert (dest / name).is_file(), name
    assert subprocess.run([sys.executable, SCRIPT, str(tmp_path / "none"), str(dest)]).returncode == 2
    # docs/validation.md states the quick run's furnace settings: those of the run.
    doc = open(os.path.join(SOURCE_DIR, "docs", "validation.md"), encoding="utf-8").read()
    e = rep["energy"]
    assert re.search(rf"^\| BSDF samples \| {e['samples']} \|", doc, flags=re.M), e["samples"]
    assert re.search(rf"^\| quadrature tolerance \| {e['quadrature_tolerance']:g} \|", doc, flags=re.M)
    assert re.search(rf"^\| BSDF samples at most \| {e['samples_max']} \|", doc, flags=re.M)


def test_committed_index_is_a_full_run():
    text = open(os.path.join(SOURCE_DIR, "docs", "validation", "README.md"), encoding="utf-8").read()
    assert "# Validation report index (full run)" in text
    assert "**FULL run." in text


def test_every_figure_the_docs_show_exists():
    for path in [os.path.join(SOURCE_DIR, "README.md")] + glob.glob(os.path.join(SOURCE_DIR, "docs", "**", "*.md"),
                                                                      recursive=True):
        text = open(path, encoding="utf-8").read()
        for name in re.findall(r"!\[[^\]]*\]\(([^)\s]+)\)", text):
            if name.startswith("http"):
                continue
            assert os.path.isfile(os.path.join(os.path.dirname(path), name)), (path, name)
