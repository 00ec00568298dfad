# Build options that do what they say (issue 47): every option() of the project's CMake files is
# listed in docs/install.md's table with the same default, the fuzz targets are built only when
# asked, and scripts/fuzz.sh builds with the -jN of the build that runs it.
import glob
import os
import re
import subprocess

from conftest import SOURCE_DIR

OPTION = re.compile(r'^\s*option\((\w+)\s+"[^"]*"\s+(\S+?)\)', re.M)
ROW = re.compile(r"^\| `(DSPBR_\w+)` \| (ON|OFF) \|", re.M)


def cmake_options():
    """{name: default} of every option() in the project's own CMake files (not tests' or examples')."""
    files = [os.path.join(SOURCE_DIR, "CMakeLists.txt"), *glob.glob(os.path.join(SOURCE_DIR, "cmake", "*.cmake")),
             *glob.glob(os.path.join(SOURCE_DIR, "*", "CMakeLists.txt"))]
    out = {}
    for f in files:
        if os.path.relpath(f, SOURCE_DIR).split(os.sep)[0] in ("tests", "examples", "fuzz"):
            continue
        out.update(dict(OPTION.findall(open(f, encoding="utf-8").read())))
    return out


def test_every_option_is_documented_with_its_default():
    options = cmake_options()
    assert "DSPBR_BUILD_PYTHON" in options and "DSPBR_FUZZ" in options  # the scan reaches python/ and the root
    documented = dict(ROW.findall(open(os.path.join(SOURCE_DIR, "docs", "install.md"), encoding="utf-8").read()))
    assert documented == options


def test_fuzz_targets_only_when_asked():
    assert cmake_options()["DSPBR_FUZZ"] == "OFF"


def fuzz_jobs(env):
    """The -j scripts/fuzz.sh would pass to its build, read from its job-selection lines."""
    script = open(os.path.join(SOURCE_DIR, "scripts", "fuzz.sh"), encoding="utf-8").read()
    lines = re.search(r'^  jobs="\$\{FUZZ_JOBS:-\}"\n.*?\n  jobs="\$\{jobs:-.*?\n', script, re.M | re.S).group(0)
    full = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "FUZZ_JOBS", "CMAKE_BUILD_PARALLEL_LEVEL")}
    return subprocess.run(["bash", "-c", lines + 'echo "$jobs"'], env={**full, **env}, capture_output=True,
                          text=True, check=True).stdout.strip()


def test_fuzz_build_takes_the_users_jobs():
    assert fuzz_jobs({"MAKEFLAGS": " -j1 --jobserver-auth=3,4"}) == "1"
    assert fuzz_jobs({"MAKEFLAGS": "w -j7"}) == "7"
    assert fuzz_jobs({"MAKEFLAGS": " -j1", "FUZZ_JOBS": "3"}) == "3"
    assert fuzz_jobs({"MAKEFLAGS": ""}) == "1"  # make without -j
    assert fuzz_jobs({"CMAKE_BUILD_PARALLEL_LEVEL": "5"}) == "5"
    assert fuzz_jobs({}) == str(os.cpu_count())
