"""The library's layering (docs/install.md, "Components"): a folder of src/dspbr/ includes headers
of its own component and of the components below it only, so that each CMake component builds
and links without the ones above it. Within core the folders are ordered too (math, io, tables,
bsdf). A lower folder including a higher one fails here before a consumer of dspbr::core fails
to link."""
import os
import re
from pathlib import Path

SOURCE = Path(os.environ.get("DSPBR_SOURCE_DIR", Path(__file__).resolve().parents[2]))
SRC = SOURCE / "src" / "dspbr"

# folder -> the folders it may include (its own included). "" is src/dspbr/ itself (core math).
CORE = ["", "io", "tables", "bsdf"]
ALLOWED = {
    "": [""],
    "io": ["", "io"],
    "tables": ["", "io", "tables"],
    "bsdf": CORE,
    "lutgen": CORE + ["lutgen"],
    "params": CORE + ["params"],
    "gltf": CORE + ["params", "gltf"],
    "scene": CORE + ["params", "gltf", "scene"],
    "validate": CORE + ["lutgen", "validate"],
    "fit": CORE + ["lutgen", "validate", "fit"],
    "conformance": CORE + ["params", "gltf", "scene", "conformance"],
    # Not components (not installed): the shader library's host side and the Vulkan plumbing of
    # `dspbr conformance run` and the shader tests.
    "shader": CORE + ["shader"],
    "vulkan": CORE + ["vulkan"],
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"dspbr/(?:([a-z_]+)/)?[a-z_0-9]+\.h"', re.M)


def folder_of(path: Path) -> str:
    rel = path.relative_to(SRC)
    return rel.parts[0] if len(rel.parts) > 1 else ""


def test_every_folder_is_assigned():
    folders = {p.name for p in SRC.iterdir() if p.is_dir()}
    assert folders == set(ALLOWED) - {""}, "a folder of src/dspbr/ has no place in the layering"


def test_no_folder_includes_a_higher_one():
    violations = []
    for path in sorted(SRC.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        here = folder_of(path)
        for m in INCLUDE.finditer(path.read_text()):
            there = m.group(1) or ""
            if there not in ALLOWED[here]:
                violations.append(f"{path.relative_to(SOURCE)} includes dspbr/{there}/")
    assert not violations, "\n".join(violations)


def test_the_check_sees_a_violation(tmp_path):
    # The pattern finds an include of a higher folder (the check above can fail).
    text = '#include "dspbr/lutgen/albedo.h"\n#include "dspbr/vec3.h"\n'
    found = [m.group(1) or "" for m in INCLUDE.finditer(text)]
    assert found == ["lutgen", ""]
    assert "lutgen" not in ALLOWED["bsdf"]
