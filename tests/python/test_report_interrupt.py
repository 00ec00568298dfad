# Ctrl-C while a report script runs (issue 45, poor list: a 34-line KeyboardInterrupt traceback):
# the scripts restore SIGINT's default action before their imports, so they end at once, by the
# signal and silently. Deterministic: the script is held at its first read of report.json, a FIFO,
# until the test has seen it open the FIFO (a writer's non-blocking open succeeds only then).
import errno
import os
import signal
import subprocess
import sys
import time

import pytest

from conftest import SOURCE_DIR


@pytest.mark.parametrize("script, fifo", [("make_report.py", ("data", "report.json")),
                                          ("conformance_report.py", ("report.json",))])
def test_ctrl_c_ends_a_report_script_without_a_traceback(tmp_path, script, fifo):
    path = tmp_path.joinpath(*fifo)
    path.parent.mkdir(parents=True, exist_ok=True)
    os.mkfifo(path)
    p = subprocess.Popen([sys.executable, os.path.join(SOURCE_DIR, "scripts", "report", script), str(tmp_path)],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    fd = None
    deadline = time.monotonic() + 60
    while fd is None and time.monotonic() < deadline and p.poll() is None:
        try:
            fd = os.open(path, os.O_WRONLY | os.O_NONBLOCK)
        except OSError as e:
            assert e.errno == errno.ENXIO, e
            time.sleep(0.02)
    assert fd is not None, f"{script} never opened {path}: {p.communicate()}"
    p.send_signal(signal.SIGINT)
    _, err = p.communicate(timeout=60)
    os.close(fd)
    assert p.returncode == -signal.SIGINT, (p.returncode, err)
    assert err == ""
