# dspbr.lut against `dspbr lut` (same settings, same numbers) and the committed tables.
import json
import os

import numpy as np
import pytest

import dspbr
from conftest import SOURCE_DIR, cli_error, run_cli

SETTINGS = dict(samples=2048, target_error=0, randomizations=4, seed=3, threads=2)
CLI_SETTINGS = ["--samples", "2048", "--target-error", "0", "--randomizations", "4", "--seed", "3", "--threads", "2"]


def cli_tables(tmp_path, tables, sizes, *extra):
    out = tmp_path / "luts"
    args = ["lut", "--out", out, "--formats", "json", "--tables", ",".join(tables), *CLI_SETTINGS, *extra]
    for name, size in sizes.items():
        args += ["--size", name + "=" + "x".join(map(str, size))]
    code, _, err = run_cli(*args)
    assert code == 0, err
    return out / "dspbr_luts.json"


@pytest.mark.parametrize("integrator,grid", [("qmc", "cell"), ("mc", "endpoint")])
def test_generate_agrees_with_cli(tmp_path, integrator, grid):
    sizes = {"GGX_E": (8, 6), "Base_E": (3, 4, 5), "Sheen_E": (4, 7), "GGX_E_avg": (5,)}
    tables = ["GGX_E", "GGX_E_avg", "Base_E", "Sheen_E"]
    got = dspbr.lut.generate(tables=tables, size=sizes, integrator=integrator, grid=grid, **SETTINGS)
    assert list(got) == tables
    for name in tables:
        assert got[name].shape == sizes[name]
        assert np.all(np.isfinite(got[name])) and got[name].min() >= 0  # plain MC is noisy at grazing
    path = cli_tables(tmp_path, tables, sizes, "--integrator", integrator, "--grid", grid)
    doc = json.loads(path.read_text())
    for name in tables:
        ref = np.array(doc["tables"][name]["values"]).reshape(sizes[name])
        np.testing.assert_allclose(got[name], ref, rtol=1e-12, atol=0)
    loaded = dspbr.lut.load(path)
    assert set(loaded) == set(tables)
    for name in tables:
        np.testing.assert_array_equal(loaded[name], got[name])


def test_generate_default_sizes_and_errors_and_threads():
    one = dspbr.lut.generate(["Sheen_ash_E"], samples=1024, target_error=0, threads=1, errors=True)
    two = dspbr.lut.generate("Sheen_ash_E", samples=1024, target_error=0, threads=2)
    values = one["Sheen_ash_E"]["values"]
    assert values.shape == tuple(len(x) for _, x in dspbr.lut.axes("Sheen_ash_E"))
    assert one["Sheen_ash_E"]["errors"].shape == values.shape
    np.testing.assert_array_equal(values, two["Sheen_ash_E"])  # bit-identical whatever the threads
    names = [n for n, _ in dspbr.lut.axes("Base_E", (2, 3, 4))]
    assert names == ["f0", "roughness", "cos_theta"]
    np.testing.assert_allclose(dspbr.lut.axes("GGX_E", (4, 4))[1][1], [0.125, 0.375, 0.625, 0.875])


def test_load_committed_tables():
    pub = dspbr.lut.load(os.path.join(SOURCE_DIR, "luts", "dspbr_luts.json"))
    assert list(pub) == dspbr.lut.names()
    doc = json.load(open(os.path.join(SOURCE_DIR, "luts", "dspbr_luts.json")))
    for name, arr in pub.items():
        axes = doc["tables"][name]["axes"]
        assert arr.shape == tuple(a["size"] for a in axes)
        np.testing.assert_array_equal(arr.ravel(), doc["tables"][name]["values"])
    ren = dspbr.lut.load(os.path.join(SOURCE_DIR, "luts", "dspbr_renderer_luts.json"))
    doc = json.load(open(os.path.join(SOURCE_DIR, "luts", "dspbr_renderer_luts.json")))
    assert set(ren) == set(doc["tables"])
    # the DSPBR 2025x tables, then the optional rough-glass ones (beyond the spec), counted apart
    assert sum(a.size for a in ren.values()) == doc["stored_values"] + doc.get("glass_stored_values", 0)
    for name, arr in ren.items():
        assert arr.shape == tuple(a["size"] for a in doc["tables"][name]["axes"])
        np.testing.assert_array_equal(arr.ravel(), doc["tables"][name]["values"])


@pytest.mark.parametrize("kwargs,cli_args", [
    ({"tables": ["GGX_F"]}, ["--tables", "GGX_F"]),
    ({"size": {"GGX_F": 4}}, ["--size", "GGX_F=4"]),
    ({"size": {"GGX_E": 4}}, ["--size", "GGX_E=4"]),
    ({"size": {"GGX_E": (0, 4)}}, ["--size", "GGX_E=0x4"]),
    ({"size": {"GGX_E": (4, 4, 4)}}, ["--size", "GGX_E=4x4x4"]),
    ({"grid": "dual"}, ["--grid", "dual"]),
    ({"integrator": "rk4"}, ["--integrator", "rk4"]),
    ({"randomizations": 1}, ["--randomizations", "1"]),
    ({"target_error": 2.0}, ["--target-error", "2"]),
])
def test_bad_settings_raise_the_cli_message(tmp_path, kwargs, cli_args):
    # Only the small GGX_E_avg table, should a bad setting ever be accepted.
    tables = kwargs.pop("tables", ["GGX_E_avg"])
    cli_tables = [] if "--tables" in cli_args else ["--tables", "GGX_E_avg"]
    msg = cli_error("lut", "--out", tmp_path / "x", "--formats", "json", "--samples", "64", *cli_tables, *cli_args)
    with pytest.raises(ValueError) as e:
        dspbr.lut.generate(tables, samples=64, **kwargs)
    assert str(e.value) == msg or "--" + str(e.value) == msg


def test_bad_threads_seed_and_files(tmp_path):
    with pytest.raises(ValueError, match=r"threads: must be a thread count \(0: all cores\) from 0 to 1024 \(decimal digits\), got '5000'"):
        dspbr.lut.generate(["GGX_E_avg"], threads=5000)
    with pytest.raises(ValueError, match="seed: must be an integer from 0 to 18446744073709551615"):
        dspbr.lut.generate(["GGX_E_avg"], seed=-1)
    with pytest.raises(ValueError, match="nothing.json"):
        dspbr.lut.load(tmp_path / "nothing.json")
    bad = tmp_path / "bad.json"
    bad.write_text("{")
    with pytest.raises(ValueError, match="bad.json"):
        dspbr.lut.load(bad)


def test_generate_renderer_layout_equals_the_committed_file():
    # The renderer layout from Python is the CLI's (the committed file was written by `dspbr lut`):
    # same stored values, bit for bit, for the tables without glass.
    made = dspbr.lut.generate(["GGX_E"], layout="renderer")
    committed = dspbr.lut.load(os.path.join(SOURCE_DIR, "luts", "dspbr_renderer_luts.json"))
    assert set(made) == {"GGX_E", "GGX_beta", "GGX_E_avg", "GGX_B_avg", "Sheen_E", "Sheen_ash_E"}
    for name, values in made.items():
        assert np.array_equal(values, committed[name]), name
    with pytest.raises(ValueError, match="layout: "):
        dspbr.lut.generate(["GGX_E"], layout="gpu")
    with pytest.raises(ValueError, match="size: the renderer layout's grids are fixed"):
        dspbr.lut.generate(["GGX_E"], {"GGX_E": (4, 4)}, layout="renderer")
