# The validation report as a reader gets it, from a quick run: the banner's colour follows the
# verdict (a passing quick run is green and tagged QUICK, not red), every case row says on how
# many views its verdict rests, the timing breakdown includes the page itself, report.html is
# the whole page in one file (every figure embedded, no link into the folder, at most 5 MB), and
# the shader library has its section with verdicts that had power.
import base64
import json
import re
import subprocess

import pytest

from conftest import dspbr_exe


@pytest.fixture(scope="module")
def quick_report(tmp_path_factory):
    out = tmp_path_factory.mktemp("report") / "r"
    p = subprocess.run([dspbr_exe(), "validate", "--quick", "--out", str(out)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr[-2000:]
    return out, p.stderr


def test_banner_colour_follows_the_verdict(quick_report):
    out, _ = quick_report
    page = (out / "index.html").read_text()
    banner = re.search(r'<p class="banner (\w+)">(.*?)</p>', page, flags=re.S)
    assert banner, "no banner"
    assert banner.group(1) == "ok"  # PASS: green, whatever the run's kind
    assert banner.group(2).startswith('<span class="quick">QUICK</span> QUICK run')
    # The case rows: "(n of m views)" beside each verdict.
    assert re.search(r'<span class="pass">PASS</span>\s*<span class="small">\(\d+ of \d+ views\)</span>', page)


def test_timing_breakdown_includes_the_page(quick_report):
    _, stderr = quick_report
    phases = re.findall(r"^  (\S[^\n]*?)\s+(\d+\.\d)s  \(cpu\s+(\d+\.\d)s\)$", stderr, flags=re.M)
    names = [p[0] for p in phases]
    assert names[0] == "energy" and names[-1] == "report (html)", names


def test_single_file_report(quick_report):
    out, _ = quick_report
    single = (out / "report.html").read_bytes()
    assert len(single) <= 5 * 1024 * 1024, len(single)
    text = single.decode()
    images = re.findall(r'<img[^>]*src="([^"]*)"', text)
    assert len(images) == len(re.findall(r"<img", (out / "index.html").read_text())) > 10
    for src in images:
        assert src.startswith("data:image/png;base64,"), src[:60]
        assert base64.b64decode(src.split(",", 1)[1])[:8] == b"\x89PNG\r\n\x1a\n"
    # No link into the report folder (the single file travels alone); outside links may stay.
    for href in re.findall(r'href="([^"]*)"', text):
        assert href.startswith(("http", "#")), href


def test_shader_library_section(quick_report):
    out, _ = quick_report
    rep = json.loads((out / "data" / "report.json").read_text())
    lib = rep["shader_library"]
    # Its verdicts are in the summary under their own names, and the quick run passes them all.
    rows = [c for c in rep["summary"] if c["check"].startswith("shader library: ")]
    names = {c["check"][len("shader library: "):].split(" (")[0] for c in rows}
    assert {"furnace: conservation", "furnace: preservation where claimed", "sampling: chi-square goodness of fit",
            "stability: no NaN / Inf / negative values, unit directions",
            "conformance: vectors within tolerance"} <= names, names
    assert sum(c["failed"] for c in rows) == 0 and sum(c["passed"] for c in rows) > 100
    # Every PASS of its furnace had power: the band of the estimate within the tolerance.
    judged = [j for r in lib["energy"]["rows"] for j in r["judged"].values() if j["status"] == "PASS"]
    assert len(judged) > 50
    for j in judged:
        assert j["band"] <= j["tolerance"], j
    # Conformance: every group judged, every vector counted once.
    groups = lib["conformance"]["groups"]
    assert len(groups) >= 10 and sum(g["vectors"] for g in groups) == lib["conformance"]["vectors"] > 100
    page = (out / "index.html").read_text()
    assert "<h2>The shader library</h2>" in page
    # Its furnace tables (the figures are the full run's: the quick run's page stays within seconds).
    section = page[page.index("<h2>The shader library</h2>"):page.index("<h2>Tables</h2>")]
    assert section.count("<h4>") >= 4 and "plots/shader_furnace_" not in section
