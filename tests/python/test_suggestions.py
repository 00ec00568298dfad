# "Did you mean" for every name users type (issue 47): parameters, tables, table layouts and
# components, in Python and on the command line (`params check` of an instance file, eval --set),
# each the same message; a name far from every valid one gets no suggestion.
import json
import subprocess

import numpy as np
import pytest

import dspbr
from conftest import cli_error, dspbr_exe


@pytest.mark.parametrize("call, expected", [
    (lambda: dspbr.Bsdf({"sheen": 1}), "unknown material parameter 'sheen'; did you mean 'sheenColor'?"),
    (lambda: dspbr.Bsdf({"roughnes": 0.3}), "unknown material parameter 'roughnes'; did you mean 'roughness'?"),
    (lambda: dspbr.Bsdf(components=["metalic"]), "components: unknown component 'metalic'; did you mean 'metallic'?"),
    (lambda: dspbr.Bsdf(tables="render"), "tables: unknown table layout 'render'; did you mean 'renderer'?"),
    (lambda: dspbr.lut.generate(["GGX_e"]), "tables: unknown table 'GGX_e'; did you mean 'GGX_E'?"),
    (lambda: dspbr.lut.generate(["Base"]), "tables: unknown table 'Base'; did you mean 'Base_E'?"),
    (lambda: dspbr.lut.generate(["GGX_E"], size={"Sheen_e": 4}, layout="published"), "size: unknown table 'Sheen_e'; did you mean 'Sheen_E'?"),
])
def test_python_suggests(call, expected):
    with pytest.raises(ValueError) as e:
        call()
    assert str(e.value).startswith(expected)


def test_no_suggestion_far_from_every_name():
    with pytest.raises(ValueError) as e:
        dspbr.Bsdf({"xyz": 1})
    assert str(e.value) == "unknown material parameter 'xyz'"


def test_cli_suggests_the_same():
    assert cli_error("eval", "--set", "sheen=1", "--view", "0,0,1", "--light", "0,0,1") == \
        "--set sheen=1: unknown material parameter 'sheen'; did you mean 'sheenColor'?"
    assert cli_error("eval", "--components", "metalic", "--view", "0,0,1", "--light", "0,0,1").startswith(
        "--components: unknown component 'metalic'; did you mean 'metallic'?")


def test_params_check_suggests(tmp_path):
    f = tmp_path / "instance.json"
    f.write_text(json.dumps({"material": "generic", "values": {"roughnes": 0.3, "sheen": [1, 1, 1]}}))
    p = subprocess.run([dspbr_exe(), "params", "check", str(f)], capture_output=True, text=True)
    assert p.returncode == 2, p
    assert f"{f}: unknown parameter 'roughnes' for material 'generic'; did you mean 'roughness'?" in p.stdout + p.stderr
    assert f"{f}: unknown parameter 'sheen' for material 'generic'; did you mean 'sheenColor'?" in p.stdout + p.stderr
