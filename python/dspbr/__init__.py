"""DSPBR 2025x reference toolchain in Python (numpy arrays in and out).

    dspbr.Bsdf(material, components=None, sheen="main", tables="renderer")
        .eval(v, l) -> (..., 3), .pdf(v, l) -> (...), .sample(v, u) -> {"l", "weight", "pdf", "flags", "valid"}
    dspbr.lut.generate(tables=None, size=None, **settings) -> {name: array} (layout="renderer" by default)
    dspbr.lut.load(path) -> {name: Table}: decoded .values, .stored, .errors, .axes (name, warp, grid, coordinates)
    dspbr.scene.analyze(path) -> dict (as `dspbr scene analyze --json`)
    dspbr.lookup.ggx_E(cos_theta, roughness), ... -> float32 arrays: the functions of the generated
        luts/dspbr_lookup.h and dspbr_glass_lookup.h, vectorised (what a renderer including them computes)
    dspbr.conformance.run(vectors, my_eval) -> results (docs/conformance.md; `import dspbr.conformance`)

Bad input raises ValueError with the one-line message the `dspbr` command prints.
"""
import sys as _sys

try:
    import numpy as _numpy  # noqa: F401  (every array in and out is numpy's)
except ImportError:
    raise ImportError(
        f"dspbr needs numpy, and the interpreter {_sys.executable} has none: use Debian's /usr/bin/python3 "
        "(apt-get install python3-numpy) or a venv made with `/usr/bin/python3 -m venv --system-site-packages`"
    ) from None

from typing import TYPE_CHECKING

from . import _dspbr as _extension
from ._dspbr import DELTA, DIFFUSE, GLOSSY, REFLECTION, TRANSMISSION, component_names, parameter_ids
from ._guard import guarded_class as _guarded_class, guarded_module as _guarded_module

if TYPE_CHECKING:  # the extension's types (its stubs, python/dspbr/_dspbr/*.pyi)
    from ._dspbr import Bsdf, lookup, lut, scene
else:  # the same, with calls it cannot convert refused in one line naming the argument (_guard.py)
    Bsdf = _guarded_class(_extension.Bsdf, "dspbr.Bsdf")
    lut = _guarded_module(_extension.lut, "dspbr.lut")
    lookup = _guarded_module(_extension.lookup, "dspbr.lookup")
    scene = _guarded_module(_extension.scene, "dspbr.scene")

__version__: str = getattr(_extension, "__version__")  # `dspbr --version`'s (git describe)

# `import dspbr.lut` and `from dspbr.scene import analyze` work like for plain submodules.
_sys.modules[__name__ + ".lut"] = lut
_sys.modules[__name__ + ".scene"] = scene
_sys.modules[__name__ + ".lookup"] = lookup

__all__ = ["Bsdf", "lut", "lookup", "scene", "parameter_ids", "component_names", "REFLECTION", "TRANSMISSION", "DELTA",
           "GLOSSY", "DIFFUSE", "__version__"]
