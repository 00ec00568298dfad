"""DSPBR 2025x reference toolchain in Python (numpy arrays in and out).

    dspbr.Bsdf(material, components=None, sheen="main", tables="renderer")
        .eval(v, l) -> (N, 3), .pdf(v, l) -> (N,), .sample(v, u) -> {"l", "weight", "pdf", "flags", "valid"}
    dspbr.lut.generate(tables=None, size=None, **settings) -> {name: array}
    dspbr.lut.load(path) -> {name: array}
    dspbr.scene.analyze(path) -> dict (as `dspbr scene analyze --json`)
    dspbr.conformance.run(vectors, my_eval) -> results (docs/conformance.md; `import dspbr.conformance`)

Bad input raises ValueError with the one-line message the `dspbr` command prints.
"""
import sys as _sys

from ._dspbr import (DELTA, DIFFUSE, GLOSSY, REFLECTION, TRANSMISSION, Bsdf, __version__, component_names, lut,
                     parameter_ids, scene)

# `import dspbr.lut` and `from dspbr.scene import analyze` work like for plain submodules.
_sys.modules[__name__ + ".lut"] = lut
_sys.modules[__name__ + ".scene"] = scene

__all__ = ["Bsdf", "lut", "scene", "parameter_ids", "component_names", "REFLECTION", "TRANSMISSION", "DELTA",
           "GLOSSY", "DIFFUSE", "__version__"]
