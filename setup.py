"""setuptools' side of `pip install --no-build-isolation .` (pyproject.toml): the extension
dspbr._dspbr is built by the project's CMake (target dspbr_python, for the interpreter running
pip), then copied where setuptools installs the package python/dspbr/.

Environment:
  DSPBR_CMAKE_BUILD_DIR  build in this folder (an existing build tree is reused: only what
                         changed is rebuilt); default: a folder under setuptools' build_temp
  DSPBR_BUILD_JOBS       parallel jobs (default: the number of CPUs)
"""
import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def project_version() -> str:
    m = re.search(r"project\(dspbr VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text())
    if not m:
        raise RuntimeError("CMakeLists.txt: no `project(dspbr VERSION ...)`")
    return m.group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        build = Path(os.environ.get("DSPBR_CMAKE_BUILD_DIR") or Path(self.build_temp).resolve() / "cmake")
        jobs = os.environ.get("DSPBR_BUILD_JOBS") or str(os.cpu_count() or 1)
        configure = ["cmake", "-S", str(ROOT), "-B", str(build)]
        if not (build / "CMakeCache.txt").exists():  # a new tree: for this interpreter, library and module only
            configure += [f"-DPython3_EXECUTABLE={sys.executable}", "-DCMAKE_BUILD_TYPE=Release",
                          "-DDSPBR_BUILD_TESTS=OFF", "-DDSPBR_BUILD_BENCH=OFF", "-DDSPBR_FUZZ=OFF",
                          "-DDSPBR_INSTALL=OFF"]
        subprocess.check_call(configure)
        subprocess.check_call(["cmake", "--build", str(build), "--target", "dspbr_python", "-j", jobs])
        # An existing tree keeps the interpreter it was configured for: its module must fit this one.
        built = build / "python" / "dspbr" / ("_dspbr" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not built.exists():
            raise RuntimeError(f"{build} holds no python/dspbr/{built.name} (a build tree configured for another "
                               f"Python than {sys.executable}? unset DSPBR_CMAKE_BUILD_DIR)")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    version=project_version(),
    # setuptools' own build folders inside the CMake one (build/, ignored by git), not beside it.
    options={"build": {"build_base": "build/setuptools"}, "egg_info": {"egg_base": "build/setuptools"}},
    ext_modules=[Extension("dspbr._dspbr", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
)
