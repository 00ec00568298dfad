# Fast start (issue 47): `dspbr` is the front that runs --version, eval, sample, params and scene
# itself; what it starts with is the dynamic libraries it needs (formerly ~270, OpenImageIO's and
# Ceres's, ~0.4 s before main), so it must not need the heavy ones. The others reach dspbr-full.
import os
import subprocess

from conftest import dspbr_exe

HEAVY = ("libOpenImageIO", "libceres", "libtbb", "libglog", "libopencv", "libgdal")


def needed(path):
    """The shared libraries the ELF file names (DT_NEEDED), from readelf."""
    out = subprocess.run(["readelf", "-d", path], capture_output=True, text=True, check=True).stdout
    return [line.split("[")[1].rstrip("]") for line in out.splitlines() if "(NEEDED)" in line]


def test_the_front_needs_no_heavy_library():
    libs = needed(dspbr_exe())
    assert "libfmt.so.9" in libs or any(lib.startswith("libfmt") for lib in libs)  # the reading works
    assert [lib for lib in libs if lib.startswith(HEAVY)] == []
    full = os.path.join(os.path.dirname(dspbr_exe()), "dspbr-full")
    assert any(lib.startswith("libOpenImageIO") for lib in needed(full))  # the check can fail


def test_the_front_runs_the_full_tool_for_the_other_commands():
    p = subprocess.run([dspbr_exe(), "lut", "--help"], capture_output=True, text=True)
    assert p.returncode == 0 and "--layout" in p.stdout
    p = subprocess.run([dspbr_exe(), "--help"], capture_output=True, text=True)
    assert p.returncode == 0 and all(f"  {c} " in p.stdout for c in ("lut", "eval", "validate", "fit", "conformance"))
    p = subprocess.run([dspbr_exe(), "lutt"], capture_output=True, text=True)
    assert p.returncode == 2 and p.stderr == "dspbr: error: unknown subcommand 'lutt'; did you mean 'lut'?\n"
    v = subprocess.run([dspbr_exe(), "--version"], capture_output=True, text=True, check=True).stdout
    assert v.startswith("dspbr ") and v == subprocess.run(
        [os.path.join(os.path.dirname(dspbr_exe()), "dspbr-full"), "--version"],
        capture_output=True, text=True, check=True).stdout
