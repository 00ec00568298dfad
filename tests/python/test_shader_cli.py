# `dspbr shader` (docs/renderer.md, "Only what a scene needs"): the header's switches follow the
# components asked for or a scene's materials, the textures listed are the tables those components
# read, and bad input is one line, exit 2.
import os
import re

from conftest import SOURCE_DIR, cli_error, run_cli


def header(tmp_path, *args):
    code, out, err = run_cli("shader", *args, "--out", str(tmp_path / "o"))
    assert code == 0, err
    return out, (tmp_path / "o" / "dspbr_specialization.h").read_text()


def switches(text):
    return {m.group(1).lower(): int(m.group(2)) for m in re.finditer(r"#define DSPBR_HAS_(\w+) (\d)", text)}


def test_components_list(tmp_path):
    out, text = header(tmp_path, "--components", "metallic,clearcoat")
    s = switches(text)
    assert len(s) == 11 and {k for k, v in s.items() if v} == {"metallic", "clearcoat"}
    assert "textures to bind: GGX_E (0) GGX_E_avg (2)" in out  # no B_c, no sheen tables


def test_scene_materials(tmp_path):
    scene = os.path.join(SOURCE_DIR, "data", "dspbr", "scenes", "sphere", "09-sheen-dielectric.gltf")
    out, text = header(tmp_path, "--scene", scene)
    assert {k for k, v in switches(text).items() if v} == {"opaque_dielectric", "sheen"}
    assert "Sheen_E (4) Sheen_ash_E (5)" in out and "GGX_beta (1)" in out


def test_bad_input(tmp_path):
    assert "did you mean 'metallic'" in cli_error("shader", "--components", "metalic", "--out", str(tmp_path / "a"))
    assert "--scene FILE or --components LIST" in cli_error("shader", "--out", str(tmp_path / "b"))
    missing = str(tmp_path / "missing.gltf")
    assert "missing.gltf" in cli_error("shader", "--scene", missing, "--out", str(tmp_path / "c"))
    assert not (tmp_path / "a").exists() and not (tmp_path / "c").exists()


def test_a_scene_name_cannot_inject_code(tmp_path):
    # The scene's file name goes into a comment of the header: a newline in it must not end the
    # comment (before, a file named "x\n#error injected\n.gltf" put an #error line into the header).
    scene = os.path.join(SOURCE_DIR, "data", "dspbr", "scenes", "sphere", "09-sheen-dielectric.gltf")
    hostile = tmp_path / "x\n#error injected\n\\.gltf"
    hostile.write_bytes(open(scene, "rb").read())
    (tmp_path / "sphere.bin").write_bytes(open(os.path.join(os.path.dirname(scene), "sphere.bin"), "rb").read())
    _, text = header(tmp_path, "--scene", str(hostile))
    assert all(line.startswith(("//", "#ifndef", "#define", "#endif")) for line in text.splitlines()), text
    assert "x\\x0a#error injected\\x0a\\.gltf" in text.splitlines()[0]
