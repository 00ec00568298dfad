# The commands docs/**/*.md show run (documentation that runs): every `dspbr ...` line of their
# indented code blocks is run and must exit 0, with every option the line shows (a renamed or
# removed option fails). Where a line shows the full settings (minutes), its run adds small ones,
# named in SMALL with the reason (None: not run, with the reason). Placeholders
# of the docs (DIR, SCENE, FILE, MATERIAL, INSTANCE...) are a fresh folder and the test data;
# `[--opt]` is run without and with the option. The README's commands are run by test_readme.py.
import glob
import os
import re
import shlex
import subprocess

import pytest

from conftest import SOURCE_DIR, dspbr_exe

DOCS = sorted(glob.glob(os.path.join(SOURCE_DIR, "docs", "**", "*.md"), recursive=True))  # design notes too
LINE = re.compile(r"^    (?:build/)?(dspbr [^#\n]*?)\s*(?:#.*)?$", re.M)


def documented():
    """(doc file name, command line without its comment) of every command the docs show."""
    out = []
    for path in DOCS:
        text = open(path, encoding="utf-8").read()
        out += [(os.path.basename(path), m.group(1)) for m in LINE.finditer(text)]
    return out


SCENE = os.path.join(SOURCE_DIR, "tests", "data", "gltf", "materials.gltf")
PARAMS = os.path.join(SOURCE_DIR, "data", "dspbr", "params-2025x.json")
INSTANCE = os.path.join(SOURCE_DIR, "tests", "data", "params", "generic_ok.json")

# Small settings added to a documented command, and why (the documented one takes minutes).
TINY_LUT = "--layout published --tables GGX_E,GGX_E_avg --size GGX_E=4x4 --size GGX_E_avg=4"
SMALL = {
    "dspbr lut --out luts": (TINY_LUT, "every table of both layouts: about 20 s, and scripts/main.sh runs it"),
    "dspbr lut --out DIR --size GGX_E=64x64 --size Base_E=16x32x32 --grid endpoint":
        ("--layout published --tables GGX_E,Base_E --target-error 1e-3", "every table at those sizes: minutes"),
    "dspbr lut --out DIR --formats exr --half": (TINY_LUT, "every table: about 15 s"),
    "dspbr lut --out DIR --integrator mc --samples 65536":
        ("--layout published --tables GGX_E --size GGX_E=4x4", "every table by plain MC: minutes"),
    "dspbr lut --out DIR --scene scene.gltf --transmission-compensation":
        ("--layout published --target-error 1e-3", "the scene's tables at full size: minutes"),
    "dspbr lut --out DIR --scene scene.gltf": ("--layout published --target-error 1e-3", "the scene's tables: a minute"),
    "dspbr lut --out DIR --tables Glass_E,Glass_inv_E,Glass_E_avg,Glass_inv_E_avg":
        ("--size Glass_E=2x2x2 --size Glass_inv_E=2x2x2 --size Glass_E_avg=2x2 --size Glass_inv_E_avg=2x2 "
         "--target-error 1e-3", "the four glass tables: about 8 s"),
    "dspbr lut --out DIR --tables GGX_E,Sheen_E": ("--size GGX_E=4x4 --size Sheen_E=4x4", "seconds instead of 10 s"),
    "dspbr lut --bench": (None, "the whole study: minutes (its two halves are run below with small settings)"),
    "dspbr lut --bench-lookups": ("--bench-points 10", "400 points: about 13 s"),
    "dspbr lut --bench-integrators --bench-csv study.csv": (None, "the integrators' study: about 42 s"),
    "dspbr lut --out DIR --layout renderer": (None, "7 s; the README's test runs the same command"),
    "dspbr lut --out DIR --quiet": (TINY_LUT, "every table: about 15 s"),
    "dspbr fit --out DIR": ("--quick", "every fit: about 2 minutes, and scripts/main.sh runs it"),
    "dspbr validate --out report": ("--quick --no-html", "the full run: minutes"),
    "dspbr validate --threads 1 --out DIR": ("--quick --no-html", "the full run: minutes"),
    "dspbr validate --quick --out DIR": ("--no-html", "the HTML report is made by the README's test of the same run"),
    "dspbr validate --quick --no-shader-library --out DIR": ("--no-html", "the HTML report is made by the README's test of a quick run"),
}


# Commands that read what the docs' preceding lines made (docs/conformance.md: generate, then the
# C harness build/example_conformance, then check): those lines are run first in the same folder,
# generate with fewer directions (seconds).
HARNESS = os.path.join(os.path.dirname(os.path.abspath(dspbr_exe())), "example_conformance")
BEFORE = {
    f"dspbr conformance check {d}/vectors.json {d}/results.csv --out {out}": [
        [dspbr_exe(), "conformance", "generate", "--directions", "2", "--no-albedo", "--out", d],
        [HARNESS, f"{d}/vectors.csv", f"{d}/results.csv"]]
    for d, out in [("conformance", "conformance-report"), ("conformance-harness", "conformance-harness/report")]
}
# `conformance run` reads the generated vectors too (the shader file is the source tree's).
BEFORE["dspbr conformance run conformance/vectors.json --glsl examples/conformance/shader_reference.glsl "
       "--out conformance-shader"] = [
    [dspbr_exe(), "conformance", "generate", "--directions", "2", "--no-albedo", "--out", "conformance"]]


def expand(command):
    """The runs of a documented line: placeholders replaced, `[--opt]` without and with."""
    optional = re.findall(r"\[(--[^\]]*)\]", command)
    base = re.sub(r"\s*\[--[^\]]*\]", "", command)
    runs = [base, base + "".join(" " + o for o in optional)] if optional else [base]
    out = []
    for r in runs:
        r = re.sub(r"\s*\[FILE\]", "", r) if r == runs[0] else r.replace("[FILE]", "FILE")
        r = (r.replace("INSTANCE...", shlex.quote(INSTANCE)).replace("SCENE", shlex.quote(SCENE))
             .replace("scene.gltf", shlex.quote(SCENE)).replace("MATERIAL", "metal")
             .replace(" FILE", " " + shlex.quote(PARAMS)))
        out.append(r)
    return out


CASES = [(doc, c, run) for doc, c in documented() for run in expand(c)]


def test_the_docs_show_commands():
    docs = {doc for doc, _ in documented()}
    assert {"luts.md", "validation.md", "params.md", "gltf_mapping.md"} <= docs, docs


@pytest.mark.parametrize("doc,command,run", CASES, ids=[f"{d}:{r.replace(SOURCE_DIR, '')}" for d, _, r in CASES])
def test_every_docs_command_runs(doc, command, run, tmp_path):
    small, reason = SMALL.get(command, ("", ""))
    if small is None:
        pytest.skip(f"{doc}: `{command}` not run: {reason}")
    args = shlex.split(run) + shlex.split(small or "")  # the documented options always run
    args = [str(tmp_path / "out") if a in ("DIR", "luts", "report") else a for a in args]
    args = [str(tmp_path / a) if a.endswith(".csv") else a for a in args]
    args = [os.path.join(SOURCE_DIR, a) if a.startswith(("examples/", "data/")) else a for a in args]
    for before in BEFORE.get(command, []):
        subprocess.run(before, cwd=tmp_path, check=True, capture_output=True, timeout=600)
    p = subprocess.run([dspbr_exe(), *args[1:]], cwd=tmp_path, capture_output=True, text=True, timeout=600)
    if p.returncode == 77 and args[1:3] == ["conformance", "run"]:
        pytest.skip("no Vulkan device")
    assert p.returncode == 0, (doc, command, args, p.stderr[-2000:])
