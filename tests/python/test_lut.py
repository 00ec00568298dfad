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
    got = dspbr.lut.generate(tables=tables, size=sizes, integrator=integrator, grid=grid, layout="published",
                             **SETTINGS)
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
        np.testing.assert_array_equal(loaded[name].values, got[name])
        assert [(a.name, a.warp) for a in loaded[name].axes] == [(n, grid) for n, _ in dspbr.lut.axes(name, sizes[name], grid)]


def test_sizes_are_integers_of_any_kind():
    # numpy's integers are integers (they were refused with "got (4, 4)"; the sixth fresh tester's
    # pass); floats and bools are not.
    plain = dspbr.lut.generate(["GGX_E_avg"], size={"GGX_E_avg": 4}, layout="published", **SETTINGS)
    numpy = dspbr.lut.generate(["GGX_E_avg"], size={"GGX_E_avg": (np.int64(4),)}, layout="published", **SETTINGS)
    np.testing.assert_array_equal(plain["GGX_E_avg"], numpy["GGX_E_avg"])
    for bad in (4.0, (np.float64(4),), True, (4, "4")):
        with pytest.raises(ValueError, match="size of GGX_E_avg expects an int or a tuple of ints"):
            dspbr.lut.generate(["GGX_E_avg"], size={"GGX_E_avg": bad}, layout="published", **SETTINGS)


def test_generate_default_sizes_and_errors_and_threads():
    one = dspbr.lut.generate(["Sheen_ash_E"], samples=1024, target_error=0, threads=1, errors=True, layout="published")
    two = dspbr.lut.generate("Sheen_ash_E", samples=1024, target_error=0, threads=2, layout="published")
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
    for name, t in pub.items():
        axes = doc["tables"][name]["axes"]
        assert t.name == name and t.layout == "published" and t.encoding == "value"
        assert t.values.shape == tuple(a["size"] for a in axes)
        np.testing.assert_array_equal(t.values.ravel(), doc["tables"][name]["values"])
        np.testing.assert_array_equal(t.stored, t.values)
        assert t.errors is not None and t.errors.shape == t.values.shape
        # the axes as lut.axes gives them for this size and grid, broadcast over the table
        for k, (a, (axis_name, x)) in enumerate(zip(t.axes, dspbr.lut.axes(name, t.values.shape, t.axes[0].warp))):
            assert a.name == axis_name and a.size == len(x)
            np.testing.assert_allclose(a.grid, x, rtol=1e-15)
            np.testing.assert_allclose(np.moveaxis(a.coordinates, k, -1).reshape(-1, a.size)[0], x, rtol=1e-15)
    ren = dspbr.lut.load(os.path.join(SOURCE_DIR, "luts", "dspbr_renderer_luts.json"))
    doc = json.load(open(os.path.join(SOURCE_DIR, "luts", "dspbr_renderer_luts.json")))
    assert set(ren) == set(doc["tables"])
    # the DSPBR 2025x tables, then the optional rough-glass ones (beyond the spec), counted apart
    assert sum(t.stored.size for t in ren.values()) == doc["stored_values"] + doc.get("glass_stored_values", 0)
    for name, t in ren.items():
        assert t.layout == "renderer"
        assert t.stored.shape == t.values.shape == tuple(a["size"] for a in doc["tables"][name]["axes"])
        np.testing.assert_array_equal(t.stored.ravel(), doc["tables"][name]["values"])
        for a in t.axes:
            np.testing.assert_allclose(a.grid, np.linspace(0, 1, a.size), rtol=1e-15)


def test_load_decodes_the_renderer_layout_as_the_c_header_looks_it_up():
    # At a sample's coordinates the generated C lookup (dspbr.lookup: float warps, Catmull-Rom
    # weights (0, 1, 0, 0) there, its own decoding) returns that sample, so decoded values and
    # coordinates are checked by code written apart from lut.load's. Tolerance: float rounding of
    # the header's warps and sums (measured worst 2.8e-6, Glass_E; Sheen_ash_E 9.5e-7 at values to 6.1). The r = 0 rows
    # hold the limit r -> 0 at fixed cos / alpha, which no lookup at r = 0 reads: checked apart;
    # the glass samples nearer ior 1 than a float argument resolves (ior < 1.001) are left out.
    ren = dspbr.lut.load(os.path.join(SOURCE_DIR, "luts", "dspbr_renderer_luts.json"))
    L = dspbr.lookup
    ior = lambda x: (2 + x) / (2 - x)  # the average tables' axis ior_x = 2 (ior - 1) / (ior + 1)
    lookups = {
        "GGX_E": lambda r, mu: L.ggx_E(mu, r),
        "GGX_E_avg": lambda r: L.ggx_E_avg(r),
        "Sheen_E": lambda a, mu: L.sheen_E(mu, a),
        "Sheen_ash_E": lambda a, mu: L.sheen_ash_E(mu, a),
        "Glass_E": lambda i, r, mu: L.glass_E(mu, r, i, 0),
        "Glass_inv_E": lambda i, r, mu: L.glass_E(mu, r, i, 1),
        "Glass_E_avg": lambda x, r: L.glass_E_avg(r, ior(x), 0),
        "Glass_inv_E_avg": lambda x, r: L.glass_E_avg(r, ior(x), 1),
        # B_avg and beta through the header's Base_E compositions at f0 = 0 (spec "Energy Preservation"):
        # E_avg = B_avg + F_ms (1 - E_m,avg), E = beta E_m + F_ms (1 - E_m), F_ms = F_ms(0, 1; E_m,avg)
        "GGX_B_avg": lambda r: L.base_E_avg(r, 0) - L.fresnel_ms(0, 1, L.ggx_E_avg(r)) * L.ggx_E_avg_missing(r),
        "GGX_beta": lambda r, mu: (L.base_E(mu, r, 0) - L.fresnel_ms(0, 1, L.ggx_E_avg(r)) * (1 - L.ggx_E(mu, r)))
        / L.ggx_E(mu, r),
    }
    assert set(lookups) == set(ren)
    for name, t in ren.items():
        got = lookups[name](*[a.coordinates.astype(np.float32) for a in t.axes])
        axes = {a.name: a for a in t.axes}
        rows = axes["roughness"].coordinates > 0 if "cos_theta" in axes and "roughness" in axes else ...
        if "ior" in axes:  # a float ior within ~1e-7 of 1 does not reach the samples near ior 1 at grazing
            rows = rows & (axes["ior"].coordinates >= 1.001)
        tol = 5e-6 * max(1.0, np.abs(t.values).max()) if name != "GGX_beta" else 2e-5
        np.testing.assert_allclose(got[rows], t.values[rows], rtol=0, atol=tol, err_msg=name)
    assert ren["GGX_E_avg"].encoding == "log_one_minus" and ren["GGX_beta"].encoding == "beta_minus_mirror"
    np.testing.assert_allclose(ren["GGX_E_avg"].values, 1 - np.exp(ren["GGX_E_avg"].stored), rtol=1e-15)
    # r = 0: cos_theta is the limit, 0 below the last sample; beta there is the mirror's, 1 at cos 0
    mu0 = ren["GGX_beta"].axes[1].coordinates[0]
    assert np.all(mu0[:-1] == 0) and mu0[-1] == 1
    np.testing.assert_array_equal(ren["GGX_beta"].values[0, :-1], 1.0)
    # glass_ior depends on cos_theta: at one ior sample the ior changes along cos_theta
    ior_axis = ren["Glass_E"].axes[0].coordinates
    assert ior_axis[5, 8].min() < ior_axis[5, 8].max()
    np.testing.assert_allclose(ior_axis[[0, -1]].reshape(2, -1), np.broadcast_to([[1], [3]], (2, ior_axis[0].size)), rtol=1e-14)


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
        dspbr.lut.generate(tables, samples=64, layout="published", **kwargs)
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
    made = dspbr.lut.generate(["GGX_E"])  # the default layout, as everywhere else
    committed = dspbr.lut.load(os.path.join(SOURCE_DIR, "luts", "dspbr_renderer_luts.json"))
    assert set(made) == {"GGX_E", "GGX_beta", "GGX_E_avg", "GGX_B_avg", "Sheen_E", "Sheen_ash_E"}
    for name, values in made.items():
        assert np.array_equal(values, committed[name].stored), name
    with pytest.raises(ValueError, match="layout: "):
        dspbr.lut.generate(["GGX_E"], layout="gpu")
    with pytest.raises(ValueError, match="size: the renderer layout's grids are fixed"):
        dspbr.lut.generate(["GGX_E"], {"GGX_E": (4, 4)}, layout="renderer")
