#!/usr/bin/env bash
# `pip install --no-build-isolation .` into a fresh venv (docs/install.md, "Python"): the venv is
# made by Debian's /usr/bin/python3 with --system-site-packages (numpy, setuptools from Debian),
# the package built from the source folder by setup.py through CMake, reusing BUILD_DIR (only
# what changed is rebuilt), then used from another folder: the installed files (stubs included),
# `python -m dspbr --version`, a Bsdf eval against the CLI's, tables of both layouts.
#   pip_install_test.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
build=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work/elsewhere"
/usr/bin/python3 -m venv --system-site-packages "$work/venv"
py="$work/venv/bin/python"
(cd "$src" && DSPBR_CMAKE_BUILD_DIR="$build" "$py" -m pip install --no-build-isolation --no-index -q .)
site=$("$py" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
for f in __init__.py __main__.py py.typed _dspbr/__init__.pyi _dspbr/lut.pyi _dspbr/scene.pyi; do
  [ -e "$site/dspbr/$f" ] || { echo "pip installed no dspbr/$f in $site"; exit 1; }
done
ls "$site"/dspbr/_dspbr*.so > /dev/null
cd "$work/elsewhere"
"$py" -m dspbr --version
DSPBR="$build/dspbr" SITE="$site" "$py" - <<'PY'
import json, os, subprocess
import numpy as np
import dspbr
assert os.path.realpath(dspbr.__file__).startswith(os.path.realpath(os.environ["SITE"])), dspbr.__file__
material = {"roughness": 0.3, "albedo": [0.8, 0.5, 0.2]}
v, l = [0.0, 0.5, 1.0], [0.3, -0.2, 1.0]
f = dspbr.Bsdf(material).eval(v, l)
cli = json.loads(subprocess.run([os.environ["DSPBR"], "eval", "--set", "roughness=0.3", "--set",
                                 "albedo=0.8,0.5,0.2", "--view", "0,0.5,1", "--light", "0.3,-0.2,1"],
                                check=True, capture_output=True, text=True).stdout)
assert np.allclose(f, cli["f"], rtol=1e-6, atol=0), (f, cli["f"])
published = dspbr.lut.generate(["GGX_E"], {"GGX_E": (4, 4)}, layout="published")
assert published["GGX_E"].shape == (4, 4)
renderer = dspbr.lut.generate(["GGX_E"])
assert renderer["GGX_E"].shape == (32, 64) and "GGX_beta" in renderer
print("pip-installed dspbr: eval agrees with the CLI, tables of both layouts generated")
PY
