# Shared helpers of the Python tests: the built `dspbr` command (DSPBR_EXE, set by CTest) run as a
# subprocess, its JSON output and its one-line error messages.
import json
import os
import subprocess

import pytest

SOURCE_DIR = os.environ.get("DSPBR_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def dspbr_exe():
    exe = os.environ.get("DSPBR_EXE")
    if not exe:
        pytest.skip("DSPBR_EXE (the built dspbr command) is not set")
    return exe


def run_cli(*args):
    """Runs `dspbr ARGS`, returns (exit status, stdout, stderr)."""
    p = subprocess.run([dspbr_exe(), *map(str, args)], capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def cli_json(*args):
    """The JSON document a command prints, without its "provenance" (version and command line,
    which the Python functions do not return)."""
    code, out, err = run_cli(*args)
    assert code == 0, err
    doc = json.loads(out)
    doc.pop("provenance", None)
    return doc


def cli_error(*args):
    """The message of `dspbr: error: MESSAGE` of a command that must fail with exit status 2."""
    code, out, err = run_cli(*args)
    assert code == 2, (code, out, err)
    line = err.strip().splitlines()[-1]
    assert line.startswith("dspbr: error: "), line
    return line[len("dspbr: error: "):]


def text(x):
    """A number / colour / vector / bool as the CLI's --set reads it, digits enough to round-trip."""
    if isinstance(x, bool):
        return "true" if x else "false"
    if hasattr(x, "tolist"):  # numpy arrays and scalars
        x = x.tolist()
    if isinstance(x, (list, tuple)):
        return ",".join(repr(float(c)) for c in x)
    if isinstance(x, str):
        return x
    return repr(float(x))


def set_args(material):
    args = []
    for k, v in material.items():
        args += ["--set", f"{k}={text(v)}"]
    return args
