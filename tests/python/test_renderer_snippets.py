# The code blocks of docs/renderer.md compile as they stand (documentation that runs): the ```cpp
# blocks with g++ -std=c++17 (and the strict warnings of the shader library's C++ entry), the
# ```glsl blocks with glslangValidator -V, the ```hlsl blocks with glslang's HLSL front end, each
# against shaders/ and luts/ of the source tree.
import os
import re
import shutil
import subprocess

import pytest

from conftest import SOURCE_DIR

DOC = os.path.join(SOURCE_DIR, "docs", "renderer.md")
BLOCK = re.compile(r"^```(cpp|glsl|hlsl)\n(.*?)^```$", re.M | re.S)
INCLUDES = ["-I" + os.path.join(SOURCE_DIR, "shaders"), "-I" + os.path.join(SOURCE_DIR, "luts")]


def blocks():
    text = open(DOC, encoding="utf-8").read()
    return [(lang, body) for lang, body in BLOCK.findall(text)]


def test_the_doc_has_a_block_per_language():
    assert sorted({lang for lang, _ in blocks()}) == ["cpp", "glsl", "hlsl"]


@pytest.mark.parametrize("index", range(len(blocks())))
def test_block_compiles(index, tmp_path):
    lang, body = blocks()[index]
    if lang == "cpp":
        src = tmp_path / "snippet.cpp"
        src.write_text(body)
        cmd = ["g++", "-std=c++17", "-Wall", "-Wextra", "-Wconversion", "-Werror", "-fsyntax-only", *INCLUDES, str(src)]
    else:
        glslang = shutil.which("glslangValidator")
        if not glslang:
            pytest.skip("glslangValidator not found")
        src = tmp_path / ("snippet.comp" if lang == "glsl" else "snippet.hlsl")
        src.write_text(body)
        cmd = [glslang, "-V", *INCLUDES, "-o", str(tmp_path / "out.spv"), str(src)]
        if lang == "hlsl":
            cmd[2:2] = ["-D", "-S", "comp", "-e", "main", "--shift-texture-binding", "2"]
    p = subprocess.run(cmd, capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
    assert "WARNING" not in p.stdout + p.stderr, p.stdout + p.stderr
