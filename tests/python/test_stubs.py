"""The Python package's typing and entry points (docs/install.md, "Python"): the committed stubs
python/dspbr/_dspbr/*.pyi are what stubgen makes from the built module (scripts/make_stubs.sh),
mypy accepts correct use and rejects wrong use through them, `python3 -m dspbr --version` works,
and an interpreter without numpy gets a message that says what to do."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

SOURCE = Path(os.environ.get("DSPBR_SOURCE_DIR", Path(__file__).resolve().parents[2]))
STUBS = SOURCE / "python" / "dspbr" / "_dspbr"
needs_mypy = pytest.mark.skipif(shutil.which("stubgen") is None or shutil.which("mypy") is None,
                                reason="mypy (Debian package mypy) not installed")


@needs_mypy
def test_committed_stubs_are_generated_from_the_module(tmp_path):
    subprocess.run(["stubgen", "-q", "-p", "dspbr._dspbr", "-o", str(tmp_path)], check=True,
                   env={**os.environ, "PYTHONPATH": os.pathsep.join(sys.path)})
    made = {p.name: p.read_text() for p in (tmp_path / "dspbr" / "_dspbr").glob("*.pyi")}
    committed = {p.name: p.read_text() for p in STUBS.glob("*.pyi")}
    assert made.keys() == committed.keys()
    for name in made:
        assert made[name] == committed[name], f"{name} is stale: run bash scripts/make_stubs.sh"


def run_mypy(tmp_path, code: str) -> subprocess.CompletedProcess:
    f = tmp_path / "use.py"
    f.write_text(code)
    return subprocess.run(["mypy", "--no-incremental", "--cache-dir", str(tmp_path / "cache"), "--strict", str(f)],
                          capture_output=True, text=True, env={**os.environ, "MYPYPATH": str(SOURCE / "python")})


@needs_mypy
def test_mypy_checks_calls_through_the_stubs(tmp_path):
    good = run_mypy(tmp_path, '''
import numpy as np
import numpy.typing as npt
import dspbr
bsdf = dspbr.Bsdf({"roughness": 0.3}, tables="published")
f: npt.NDArray[np.float64] = bsdf.eval([0.0, 0.0, 1.0], np.array([[0.3, 0.0, 1.0]]))
names: list[str] = dspbr.lut.names() + bsdf.components
version: str = dspbr.__version__
table: dspbr.lut.Table = dspbr.lut.load("luts/dspbr_renderer_luts.json")["GGX_E"]
cos: npt.NDArray[np.float64] = table.axes[1].coordinates
''')
    assert good.returncode == 0, good.stdout + good.stderr
    bad = run_mypy(tmp_path, '''
import dspbr
bsdf = dspbr.Bsdf(sheen=2)
n: int = dspbr.lut.names()
warp: int = dspbr.lut.load("x.json")["GGX_E"].axes[0].warp
''')
    assert bad.returncode == 1, bad.stdout
    assert 'Argument "sheen" to "Bsdf" has incompatible type "int"; expected "str"' in bad.stdout
    assert 'Incompatible types in assignment (expression has type "List[str]", variable has type "int")' in bad.stdout
    assert 'Incompatible types in assignment (expression has type "str", variable has type "int")' in bad.stdout


def test_module_version_entry_point():
    out = subprocess.run([sys.executable, "-m", "dspbr", "--version"], capture_output=True, text=True, check=True)
    import dspbr
    assert out.stdout.startswith(f"dspbr {dspbr.__version__} (")


def test_a_python_without_numpy_is_told_what_to_do():
    # numpy made unimportable in a fresh interpreter (sys.modules entry None).
    out = subprocess.run([sys.executable, "-c", "import sys; sys.modules['numpy'] = None; import dspbr"],
                         capture_output=True, text=True)
    assert out.returncode == 1
    last = out.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: dspbr needs numpy, and the interpreter ")
    assert "python3-numpy" in last and "--system-site-packages" in last
