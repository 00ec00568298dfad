# dspbr.scene.analyze against `dspbr scene analyze --json`.
import glob
import json
import os

import pytest

import dspbr
from conftest import SOURCE_DIR, cli_error, cli_json

SCENES = sorted(glob.glob(os.path.join(SOURCE_DIR, "data", "dspbr", "scenes", "sphere", "*.gltf")))


@pytest.mark.parametrize("path", SCENES[::9] + SCENES[-1:])
def test_analyze_agrees_with_cli(path):
    assert dspbr.scene.analyze(path) == cli_json("scene", "analyze", "--json", path)
    assert dspbr.scene.analyze(path, parameters=True) == cli_json("scene", "analyze", "--json", "--parameters", path)


def test_material_instance(tmp_path):
    path = tmp_path / "m.json"
    path.write_text(json.dumps({"material": "generic", "values": {"sheenColor": [1, 1, 1], "clearcoat": 1}}))
    got = dspbr.scene.analyze(str(path))
    assert got == cli_json("scene", "analyze", "--json", path)
    assert "Sheen_E" in got["tables"] and got["materials"][0]["components"]


def test_bad_files_raise_the_cli_message(tmp_path):
    bad = tmp_path / "broken.gltf"
    bad.write_text('{"asset": ')
    for path in [bad, tmp_path / "missing.gltf"]:
        msg = cli_error("scene", "analyze", "--json", path)
        with pytest.raises(ValueError) as e:
            dspbr.scene.analyze(path)
        assert str(e.value) == msg


def test_scene_folders_beyond_the_material_limit_are_refused(tmp_path):
    # limits.h kSceneMaterials (10,000; docs/limits.md): two files of 5,001 empty materials each are
    # within the per-file limit; the folder (conformance generate --scenes) and the run (scene
    # analyze) are not, and are refused before any vector or analysis is printed.
    doc = {"asset": {"version": "2.0"}, "materials": [{}] * 5001}
    for name in ("a.gltf", "b.gltf"):
        (tmp_path / name).write_text(json.dumps(doc))
    message = cli_error("conformance", "generate", "--out", tmp_path / "v", "--scenes", tmp_path, "--no-albedo",
                        "--directions", "1")
    assert message == f"--scenes: {tmp_path / 'b.gltf'}: the scene folder holds more than 10000 materials, the limit (docs/limits.md)"
    assert not (tmp_path / "v").exists()
    message = cli_error("scene", "analyze", tmp_path)
    assert message.startswith(f"{tmp_path / 'b.gltf'}: the run's scenes hold more than 10000 materials")
    assert dspbr.scene.analyze(str(tmp_path / "a.gltf"))["materials"][5000]["name"] == "material 5000"
