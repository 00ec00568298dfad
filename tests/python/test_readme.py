# The README's commands run as shown (issue: documentation that runs): every `build/dspbr ...`
# line of its indented code blocks is run in a fresh folder, with the material file the README
# shows, and must exit 0; the quick start's commands also print or write what the README says.
import json
import os
import re
import shlex
import subprocess

import pytest

from conftest import SOURCE_DIR, dspbr_exe

README = open(os.path.join(SOURCE_DIR, "README.md"), encoding="utf-8").read()
COMMANDS = re.findall(r"^    (build/dspbr .*)$", README, flags=re.M)


def run(command, cwd):
    args = shlex.split(command)
    assert args[0] == "build/dspbr"
    return subprocess.run([dspbr_exe(), *args[1:]], cwd=cwd, capture_output=True, text=True)


def test_the_readme_shows_the_quick_start():
    start = README.index("## Quick start")
    quick = [c for c in COMMANDS if README.index(c) > start][:3]
    assert [shlex.split(c)[1] for c in quick] == ["eval", "lut", "validate"]
    assert README.index("## Quick start") < README.index("## Set-up on a fresh machine")


@pytest.mark.parametrize("command", COMMANDS)
def test_every_readme_command_runs(command, tmp_path):
    material = re.search(r"`my_material.json` a material instance.*?```json\n(.*?)```", README, flags=re.S)
    (tmp_path / "my_material.json").write_text(material.group(1))
    p = run(command, tmp_path)
    assert p.returncode == 0, (command, p.stderr[-2000:])
    sub = shlex.split(command)[1]
    if sub in ("eval", "sample"):
        doc = json.loads(p.stdout)
        assert "provenance" in doc
    if command.startswith("build/dspbr eval --set roughness=0.3 --set albedo=1,0.5,0.2"):
        # The values the quick start quotes, to the digits it quotes them.
        doc = json.loads(p.stdout)
        quoted = re.search(r'`"f": \[([^\]]*)\]` \(f without the cosine\), `"pdf": ([0-9.]+)`', README)
        for got, text in zip(doc["f"], quoted.group(1).split(",")):
            assert f"{got:.3g}" == text.strip(), (doc["f"], quoted.group(1))
        assert f"{doc['pdf']:.3g}" == quoted.group(2)
        assert doc["components"] == ["opaque_dielectric"]
    if sub == "lut":
        out = tmp_path / "my_tables"
        for name in ("dspbr_lookup.h", "dspbr_lookup.glsl", "dspbr_lookup.hlsl", "dspbr_renderer_luts.json"):
            assert (out / name).is_file(), name
        assert any((out / "renderer").iterdir())
    if sub == "validate":
        assert (tmp_path / "my_report" / "index.html").is_file()
        # The counts and the banner the README quotes, as printed.
        quoted = re.search(r"`furnace: conservation\s+\(E <= 1 \+ tol\)((?:\s+\d+){4})`", README)
        counts = quoted.group(1).split()
        assert re.search(r"furnace: conservation \(E <= 1 \+ tol\) +" + " +".join(counts) + r"\n", p.stdout), p.stdout
        banner = re.search(r"a banner that begins `([^`]*)`", README).group(1)
        assert "\n  " + banner in p.stdout, p.stdout
