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


def alive(pid):
    # A process that has not ended within 2 s; a zombie (ended, its parent gone, not yet reaped
    # by init) counts as ended.
    deadline = time.monotonic() + 2
    while time.monotonic() < deadline:
        try:
            with open(f"/proc/{pid}/stat") as f:
                if f.read().rsplit(")", 1)[1].split()[0] in "ZX":
                    return False
        except FileNotFoundError:
            return False
        time.sleep(0.02)
    return True


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


def test_an_interrupt_stops_what_the_report_script_started(tmp_path):
    # SIGINT to dspbr alone (not its process group, as `kill PID` does) while its report script
    # runs: the script and every process it started end with it (before: make_report.py's worker
    # processes outlived the run, held the caller's output pipe and slept forever). The stand-in
    # "python" starts a background process that ignores SIGINT (sh runs `&` jobs so) and waits.
    from conftest import run_cli, dspbr_exe
    code, _, err = run_cli("conformance", "generate", "--directions", 1, "--no-albedo", "--no-scenes",
                           "--out", tmp_path / "v")
    assert code == 0, err
    vectors = tmp_path / "v" / "vectors.json"
    code, _, err = run_cli("conformance", "reference", vectors, "--out", tmp_path / "r.json")
    assert code == 0, err
    marker = tmp_path / "started"
    python = tmp_path / "python"
    python.write_text(f'#!/bin/sh\n[ "$1" = "-c" ] && exit 0\nsleep 300 &\necho $! > {marker}\nwait\n')
    python.chmod(0o755)
    p = subprocess.Popen([dspbr_exe(), "conformance", "check", str(vectors), str(tmp_path / "r.json"),
                          "--python", str(python), "--out", str(tmp_path / "report")],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    deadline = time.monotonic() + 60
    while not (marker.exists() and marker.read_text().strip()) and time.monotonic() < deadline:
        time.sleep(0.02)
    sleeper = int(marker.read_text())
    p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=60)  # hung before: the sleeper held the pipes
    assert p.returncode == 128 + signal.SIGINT, (out, err)
    assert "interrupted (SIGINT)" in err
    assert not alive(sleeper)
    assert not (tmp_path / "report").exists()
    assert [n for n in os.listdir(tmp_path) if n.startswith(".dspbr")] == []
