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

from . import _dspbr as _extension
from ._dspbr import (DELTA, DIFFUSE, GLOSSY, REFLECTION, TRANSMISSION, Bsdf, component_names, lookup, lut,
                     parameter_ids, scene)

__version__: str = getattr(_extension, "__version__")  # `dspbr --version`'s (git describe)

# `import dspbr.lut` and `from dspbr.scene import analyze` work like for plain submodules.
_sys.modules[__name__ + ".lut"] = lut
_sys.modules[__name__ + ".scene"] = scene
_sys.modules[__name__ + ".lookup"] = lookup

__all__ = ["Bsdf", "lut", "lookup", "scene", "parameter_ids", "component_names", "REFLECTION", "TRANSMISSION", "DELTA",
           "GLOSSY", "DIFFUSE", "__version__"]
