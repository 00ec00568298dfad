#!/usr/bin/env python3
"""Writes one patched copy of the shader library per seeded mistake (seeded_mistakes.json).

usage: seed_mistakes.py SHADERS_DIR MISTAKES_JSON OUT_DIR

OUT_DIR/NAME/ gets the entries dspbr.h, dspbr.glsl, dspbr.hlsl and dspbr/*.glsl|*.h|*.hlsl of
SHADERS_DIR (so that a GLSL or HLSL kernel compiles against the copy too) with the namespace
dspbr_shader renamed dspbr_seeded_NAME (each copy compiles into its own namespace, so that the
copies and the library link into one program without two bodies for one inline function) and the
mistake's patches applied: "find" must occur exactly once in its file, "append" adds text at the
end. A file is rewritten only when its text changes (no needless rebuilds). Exit 1 naming the
patch that does not apply.
"""
import json
import pathlib
import sys


def write_if_changed(path, text):
    if path.exists() and path.read_text() == text:
        return
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)


def seeded_copy(shaders, mistake, out):
    name = mistake["name"]
    files = {entry: (shaders / entry).read_text() for entry in ("dspbr.h", "dspbr.glsl", "dspbr.hlsl")}
    for p in sorted((shaders / "dspbr").iterdir()):
        if p.is_file():
            files["dspbr/" + p.name] = p.read_text()
    for key in files:
        files[key] = files[key].replace("dspbr_shader", "dspbr_seeded_" + name)
    for patch in mistake["patches"]:
        key = patch["file"]
        if key not in files:
            raise SystemExit(f"seed_mistakes: {name}: no file {key} in {shaders}")
        if "append" in patch:
            files[key] += patch["append"]
            continue
        count = files[key].count(patch["find"])
        if count != 1:
            raise SystemExit(f"seed_mistakes: {name}: {key} holds {count} copies of {patch['find']!r} (needs 1)")
        files[key] = files[key].replace(patch["find"], patch["replace"])
    for key, text in files.items():
        write_if_changed(out / name / key, text)


def main():
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    shaders, spec, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    for mistake in json.loads(spec.read_text())["mistakes"]:
        seeded_copy(shaders, mistake, out)


if __name__ == "__main__":
    main()
