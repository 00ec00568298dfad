# Untrusted input through Python (docs/limits.md, "Messages", "Confinement", "Input files"): bad
# values raise ValueError, wrong types TypeError, a failed allocation MemoryError, each one line
# with the command line's wording and no binding-library text; files outside a glTF's folder and
# files that are not regular files are refused as by the command.
import json
import os

import numpy as np
import pytest

import dspbr
from conftest import cli_error

BINDING_WORDS = ("pybind11", "incompatible function arguments", "Invoked with", "TypeError:")


def one_line(e):
    text = str(e.value)
    assert "\n" not in text, text
    assert not any(w in text for w in BINDING_WORDS), text
    return text


def test_integers_beyond_a_double_and_out_of_range():
    with pytest.raises(ValueError) as e:
        dspbr.Bsdf({"roughness": 10**30})
    assert one_line(e) == "parameter 'roughness' = 1e+30 is outside [0, 1]"
    with pytest.raises(ValueError) as e:
        dspbr.Bsdf({"roughness": 10**400})
    assert "is beyond the range of a double" in one_line(e)
    assert len(str(e.value)) < 400  # the 401-digit integer is cut


def test_integer_settings_have_the_cli_wording():
    with pytest.raises(ValueError) as e:
        dspbr.lut.generate(["GGX_E_avg"], threads=2**40)
    msg = cli_error("lut", "--threads", str(2**40), "--tables", "GGX_E_avg", "--out", "unused")
    assert "--" + one_line(e) == msg
    with pytest.raises(ValueError) as e:
        dspbr.lut.generate(["GGX_E_avg"], seed=-1)
    assert one_line(e).startswith("seed: must be an integer from 0 to 18446744073709551615")
    for kwargs in ({"threads": "2"}, {"seed": 1.5}, {"randomizations": True}):
        with pytest.raises(TypeError) as e:
            dspbr.lut.generate(["GGX_E_avg"], **kwargs)
        assert "must be an integer" in one_line(e)


def test_a_failed_allocation_is_a_memory_error():
    # A (10^12, 3) broadcast view costs nothing; its contiguous copy (22 TB) cannot be made.
    bsdf = dspbr.Bsdf({"roughness": 0.5})
    huge = np.broadcast_to(np.array([0.0, 0.2, 1.0]), (10**12, 3))
    with pytest.raises(MemoryError):
        bsdf.eval([0, 0, 1], huge)
    with pytest.raises(MemoryError):
        bsdf.sample([0, 0, 1], np.broadcast_to(np.array([0.1, 0.2, 0.3]), (10**12, 3)))


def test_scene_uris_stay_inside_the_folder(tmp_path):
    (tmp_path / "secret.bin").write_bytes(b"s" * 24)
    scene = tmp_path / "scene"
    scene.mkdir()
    doc = {"asset": {"version": "2.0"}, "buffers": [{"byteLength": 24, "uri": "../secret.bin"}],
           "bufferViews": [{"buffer": 0, "byteLength": 24}], "materials": [{}]}
    path = scene / "s.gltf"
    path.write_text(json.dumps(doc))
    with pytest.raises(ValueError) as e:
        dspbr.scene.analyze(path)
    assert one_line(e) == cli_error("scene", "analyze", path)
    assert one_line(e) == f"{path}: buffers[0]: URI '../secret.bin' leaves the glTF's folder"


def test_only_regular_files_are_read(tmp_path):
    fifo = tmp_path / "tables.json"
    os.mkfifo(fifo)
    with pytest.raises(ValueError) as e:  # would block forever if opened as a plain file
        dspbr.lut.load(fifo)
    assert one_line(e) == f"{fifo} is not a regular file (a FIFO)"
    with pytest.raises(ValueError) as e:
        dspbr.scene.analyze("/dev/zero")
    assert one_line(e) == "/dev/zero is not a regular file (a character device)"


def test_results_that_overflow_are_errors_not_none(tmp_path):
    doc = {"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_materials_emissive_strength"],
           "materials": [{"emissiveFactor": [1e308, 1e308, 1e308],
                          "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 1e308}}}]}
    path = tmp_path / "bright.gltf"
    path.write_text(json.dumps(doc))
    with pytest.raises(ValueError) as e:  # refused where the glTF is read, naming the material
        dspbr.scene.analyze(path, parameters=True)
    assert one_line(e) == (f"{path}: materials[0] 'material 0': emissiveFactor x "
                           "KHR_materials_emissive_strength.emissiveStrength is beyond the largest number")


def test_a_nul_byte_in_a_file_name_is_refused(tmp_path):
    good = tmp_path / "t.json"
    good.write_text("{}")
    with pytest.raises(ValueError) as e:  # the C path would end at the NUL and open t.json
        dspbr.lut.load(str(good) + "\0x")
    assert one_line(e).endswith(": a file name cannot hold a NUL byte")
