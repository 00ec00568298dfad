# Ctrl-C during dspbr.lut.generate (issue 45, poor list: it was ignored until the generation
# returned, minutes later): the generation runs on a worker thread while the calling thread checks
# Python's signals, so KeyboardInterrupt comes within about a second. The child process sends
# SIGINT to itself one second into a generation that would take hours (256x256 cells of 2^20 plain
# Monte Carlo samples each); the parent's timeout only guards against a hang.
import subprocess
import sys

CHILD = r"""
import os, signal, sys, threading, time
import dspbr
threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
start = time.monotonic()
try:
    dspbr.lut.generate(["GGX_E"], {"GGX_E": [256, 256]}, layout="published", integrator="mc", samples=1 << 20,
                       target_error=0, threads=1)
    print("finished")
except KeyboardInterrupt:
    print("interrupted")
"""


def test_ctrl_c_interrupts_a_long_generation():
    p = subprocess.run([sys.executable, "-c", CHILD], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr[-2000:]
    assert p.stdout.strip() == "interrupted", p.stdout + p.stderr[-2000:]
