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
