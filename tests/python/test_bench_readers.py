# The reader benchmark (scripts/bench_readers.py, docs/limits.md "Reading cost"; issue 45) run at a
# sixteenth of its sizes: every reader's peak memory within 10 x the input + 200 MB and an exit
# status that is a verdict (0, 1 or 2), never a crash. Its time ratios are the benchmark's to report
# (no timed assertion here); the memory bound has power: a reader at 55 x its input (what JSON of
# empty objects cost before the readers' bound) would exceed it on the 4 MB glTF.
import json
import os
import subprocess
import sys

from conftest import SOURCE_DIR, dspbr_exe


def test_every_reader_within_the_memory_bound(tmp_path):
    out = tmp_path / "readers.json"
    p = subprocess.run([sys.executable, os.path.join(SOURCE_DIR, "scripts", "bench_readers.py"), "--dspbr",
                        dspbr_exe(), "--scale", "0.0625", "--json", str(out)], capture_output=True, text=True)
    assert p.returncode in (0, 1), p.stderr  # 1: a time ratio or a bound exceeded, judged below
    doc = json.loads(out.read_text())
    assert len(doc["readers"]) == 11
    for row in doc["readers"]:
        for run in row["runs"]:
            assert run["exit"] in (0, 1, 2), (row["reader"], run)
            assert run["peak_mb"] <= 10 * run["bytes"] / 1e6 + 200, (row["reader"], run)
            if run["exit"] == 2:  # refused in one line
                assert run["message"].startswith("dspbr: error: "), run
    assert doc["readers"][2]["runs"][1]["bytes"] > 4e6  # the glTF rows are the sizes the docstring says


def test_bad_usage_exits_2():
    p = subprocess.run([sys.executable, os.path.join(SOURCE_DIR, "scripts", "bench_readers.py"), "--dspbr",
                        "/nonexistent/dspbr"], capture_output=True, text=True)
    assert p.returncode == 2 and "not an executable" in p.stderr
