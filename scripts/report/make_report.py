#!/usr/bin/env python3
"""Builds the validation report DIR/index.html (+ DIR/plots/*.png and *.csv) from the data
DIR/data/report.json written by `dspbr validate`. Run with /usr/bin/python3 (numpy, matplotlib,
jinja2). Every figure is written as PNG (plus a small *_thumb.png shown on the page, linking to
the full one) together with a CSV of the numbers it shows.

usage: make_report.py DIR
"""
import signal

# SIGINT ends the script at once and without a traceback (SIGTERM does by default): dspbr,
# interrupted with it, says so in one line and discards the report folder (docs/limits.md).
signal.signal(signal.SIGINT, signal.SIG_DFL)
import base64
import csv
import itertools
import json
import math
import os
import re
import sys
import textwrap
from concurrent.futures import ProcessPoolExecutor

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402
from jinja2 import Environment, FileSystemLoader, select_autoescape  # noqa: E402
from PIL import Image  # noqa: E402  (matplotlib's own dependency)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import integrator_plot  # noqa: E402  (the plot docs/luts.md shows, from the same data)

HERE = os.path.dirname(os.path.abspath(__file__))
THUMB_WIDTH = 1000  # px: figures wider than this are shown as thumbnails linking to the full PNG

# Words for the identifiers of report.json (the glossary of the page explains them).
CLAIM_WORDS = {"preserving": "preserving (E = 1 claimed)", "conserving": "conserving (E ≤ 1 only)",
               "gains_by_spec": "gains energy by the spec"}
AXIS_WORDS = {"roughness": "roughness r", "cos_theta": "cos θ (view)", "f0": "f0", "alpha_b": "α_b = r_b² (sheen)"}
TABLE_UNIT = {"GGX_E": "E_m", "GGX_E_avg": "E_m,avg", "Base_E": "E", "Base_E_avg": "E_avg",
              "Sheen_E": "E_b", "Sheen_ash_E": "E_b (alt.)"}


def words(s):
    """An identifier of report.json as words: component names, check names."""
    for a, b in (("_", " "), ("<=", "≤"), (">=", "≥"), ("eta^2", "η²"), (" - P(delta) - P(fail)", " − P(δ) − P(fail)")):
        s = s.replace(a, b)
    return s


def slug(s):
    return "".join(c if c.isalnum() else "_" for c in s).strip("_")


def axis_coord(a, i):
    """Position of sample i on a table axis (cell-centred or endpoint grid)."""
    if a["kind"] == "cell_centred":
        return a["lo"] + (i + 0.5) / a["size"] * (a["hi"] - a["lo"])
    return a["lo"] + i / max(a["size"] - 1, 1) * (a["hi"] - a["lo"])


class Figures:
    def __init__(self, out):
        self.out = out
        os.makedirs(os.path.join(out, "plots"), exist_ok=True)

    def save(self, fig, name, header, rows):
        """Figures use constrained layout (no bbox_inches="tight": one draw less per figure)."""
        png = f"plots/{name}.png"
        csv_path = f"plots/{name}.csv"
        fig.savefig(os.path.join(self.out, png), dpi=110)
        plt.close(fig)
        with open(os.path.join(self.out, csv_path), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(header)
            w.writerows(rows)
        return {"png": png, "csv": csv_path, "thumb": self.thumbnail(png)}

    def thumbnail(self, png):
        """A Lanczos-resampled copy THUMB_WIDTH wide (the PNG itself when not wider)."""
        with Image.open(os.path.join(self.out, png)) as img:
            if img.width <= THUMB_WIDTH:
                return png
            small = img.convert("RGB").resize((THUMB_WIDTH, round(img.height * THUMB_WIDTH / img.width)),
                                              Image.LANCZOS).quantize(256)  # palette PNG: a few tens of kB
        thumb = png[:-4] + "_thumb.png"
        small.save(os.path.join(self.out, thumb), optimize=True)
        return thumb


def legend_above(ax, handles, labels, ncol):
    """A legend above the axes, off the data (constrained layout makes room for it)."""
    ax.legend(handles, labels, loc="lower left", bbox_to_anchor=(0.0, 1.0), ncol=ncol, fontsize=8, frameon=False)


def furnace_plots(rep, figs, part=None, energy=None, name="furnace"):
    """One panel per case: E − 1 by the quadrature (its stated error as the bar) and the sampled
    estimator (±4σ bars), tolerance lines; one legend above the panels. energy: the furnace data
    (rep["energy"] by default; the shader library's with name "shader_furnace"). figs None: the
    tables' data alone, no figure."""
    energy = rep["energy"] if energy is None else energy
    tol = energy["tolerances"]
    k = tol["sigmas"]
    rows_by_case = {}
    for r in energy["rows"]:
        rows_by_case.setdefault(r["case"], []).append(r)
    groups = {}
    for c in energy["cases"]:
        groups.setdefault(c["component"], []).append(c)
    out = []
    for i, (comp, cs) in enumerate(groups.items()):
        if part is not None and i % 2 != part:
            continue  # the other half (drawn by another process)
        # Every (case, view) row with the band and tolerance each verdict used.
        table = {"component": comp, "cases": cs,
                 "rows": [{"case": c["case"], "cos": r["cos"], "judged": r.get("judged", {})}
                          for c in cs for r in sorted(rows_by_case[c["case"]], key=lambda r: -r["cos"])]}
        if figs is None:
            out.append(table)
            continue
        ncol = min(len(cs), 4)
        nrow = math.ceil(len(cs) / ncol)
        fig, grid = plt.subplots(nrow + 1, ncol, figsize=(max(3.1 * ncol, 6.0), 2.5 * nrow + 0.7), squeeze=False,
                                 layout="constrained", height_ratios=[0.7 / 2.5] + [1] * nrow)
        top = grid[0, 0].get_gridspec()
        for ax in grid[0]:
            ax.remove()
        legend_ax = fig.add_subplot(top[0, :])
        legend_ax.axis("off")
        axes = grid[1:]
        csv_rows = []
        handles = {}
        for ax, c in zip(axes.ravel(), cs):
            rs = sorted(rows_by_case[c["case"]], key=lambda r: r["cos"])
            x = np.array([r["cos"] for r in rs])
            ys = np.array([r["sampled"][1] for r in rs]) - 1
            es = np.array([r["sampled_se"][1] for r in rs])
            yn = np.array([r["non_delta"][1] for r in rs]) - 1
            en = np.array([r.get("non_delta_se", r["sampled_se"])[1] for r in rs])
            ye = np.array([r["quadrature"][1] for r in rs]) - 1
            ee = np.array([r["quadrature_error"] for r in rs])
            dx = 0.012 * (x.max() - x.min() if len(x) > 1 else 1)
            handles["s"] = ax.errorbar(x - dx, ys, yerr=k * es, fmt="o", ms=3, capsize=2, color="C0")
            if np.any(np.abs(yn - ys) > 1e-9):
                handles["n"] = ax.errorbar(x, yn, yerr=k * en, fmt="s", ms=2.5, capsize=2, color="0.5")
            handles["e"] = ax.errorbar(x + dx, ye, yerr=ee, fmt="x", ms=4, capsize=2, color="C1")
            handles["z"] = ax.axhline(0.0, color="k", lw=0.8)
            handles["c"] = ax.axhline(tol["conservation"], color="r", lw=0.7, ls="--")
            if c["claim"] == "preserving":
                handles["p"] = ax.axhline(-c.get("preservation_tol", tol["preservation"]), color="b", lw=0.7, ls="--")
            # y range from the estimates and limits, not the error bars: a wide sampled bar (heavy
            # tails at grazing view) runs off the panel instead of flattening it.
            pts = np.concatenate([ys, ye, yn if "n" in handles else ys, [0.0, tol["conservation"]]])
            lo, hi = float(np.min(pts)), float(np.max(pts))
            pad = 0.15 * (hi - lo) + 0.01
            ax.set_ylim(lo - pad, hi + pad)
            ax.set_title(c["case"], fontsize=8)
            ax.set_xlabel("cos θ_v (< 0: viewer inside)", fontsize=7)
            ax.tick_params(labelsize=7)
            ax.grid(alpha=0.3)
            for r in rs:
                csv_rows.append([c["case"], r["cos"], *r["sampled"], *r["sampled_se"], *r["non_delta"],
                                 *r["quadrature"], r["quadrature_error"], r["samples"], r["invalid_fraction"], *[r["verdicts"].get(v, "")
                                                                          for v in ("agreement", "conservation",
                                                                                    "preservation")]])
        for ax in axes.ravel()[len(cs):]:
            ax.axis("off")
        for ax in axes[:, 0]:
            ax.set_ylabel("E − 1", fontsize=8)
        labels = {"s": f"BSDF-sampled, all lobes (±{k:g}σ)", "n": f"BSDF-sampled, non-delta lobes (±{k:g}σ)",
                  "e": "quadrature of eval, non-delta (± its stated error)", "z": "E = 1",
                  "c": f"conservation limit 1 + {tol['conservation']:g}", "p": "preservation limit (claimed)"}
        keys = [q for q in "snezcp" if q in handles]
        legend_ax.legend([handles[q] for q in keys], [labels[q] for q in keys], loc="center", ncol=2 if ncol == 1 else 3,
                         fontsize=7, frameon=False)
        f = figs.save(fig, f"{name}_{slug(comp)}",
                      ["case", "cos", "sampled_r", "sampled_g", "sampled_b", "se_r", "se_g", "se_b", "non_delta_r",
                       "non_delta_g", "non_delta_b", "quadrature_r", "quadrature_g", "quadrature_b",
                       "quadrature_error", "samples", "invalid_fraction", "agreement", "conservation", "preservation"], csv_rows)
        f.update(table)
        out.append(f)
    return out


def split_strip(rgb, n, res):
    gap = (rgb.shape[1] - n * res) // max(n - 1, 1)
    return [rgb[:, k * (res + gap):k * (res + gap) + res] for k in range(n)]


def sphere_plots(rep, figs, out_dir):
    """Per row: the pictures on a neutral grey background (top) and E − 1 in false colour (bottom)
    with a colour bar whose arrows mark clipping; the true range is in the title."""
    out = []
    lim = 0.2
    for row in rep["furnace_images"]:
        n = len(row["values"])
        res = row["res"]
        pics = split_strip(plt.imread(os.path.join(out_dir, row["png"]))[:, :, :3], n, res)
        fig, axes = plt.subplots(2, n, figsize=(1.9 * n + 1.2, 4.2), squeeze=False, layout="constrained")
        yy, xx = np.mgrid[0:res, 0:res]
        inside = ((xx + 0.5) / res * 2 - 1) ** 2 + (1 - (yy + 0.5) / res * 2) ** 2 < 1
        csv_rows = []
        im = None
        lo, hi = np.inf, -np.inf
        for k, (val, alb, pic) in enumerate(zip(row["values"], row["albedo_green"], pics)):
            shown = np.where(inside[..., None], pic, 0.5)  # neutral grey outside the sphere
            axes[0, k].imshow(shown, interpolation="nearest")
            axes[0, k].add_patch(plt.Circle((res / 2 - 0.5, res / 2 - 0.5), res / 2, fill=False, color="0.25", lw=0.6))
            axes[0, k].set_title(f"{row['parameter']} = {val:g}", fontsize=8)
            a = np.array(alb, dtype=float).reshape(res, res)
            dev = np.where(inside, a - 1.0, np.nan)
            im = axes[1, k].imshow(dev, cmap="RdBu_r", vmin=-lim, vmax=lim, interpolation="nearest")
            for ax in axes[:, k]:
                ax.set_xticks([])
                ax.set_yticks([])
                for sp in ax.spines.values():
                    sp.set_visible(False)
            d = a[inside] - 1.0
            lo, hi = min(lo, d.min()), max(hi, d.max())
            csv_rows.append([row["name"], val, float(d.mean()), float(d.min()), float(d.max())])
        extend = {(False, False): "neither", (True, False): "min", (False, True): "max", (True, True): "both"}[
            (lo < -lim, hi > lim)]
        cb = fig.colorbar(im, ax=axes[1, :].tolist(), shrink=0.9, extend=extend)
        cb.set_label("E − 1 (no unit)", fontsize=8)
        cb.ax.tick_params(labelsize=7)
        axes[0, 0].set_ylabel("picture", fontsize=8)
        axes[1, 0].set_ylabel("E − 1", fontsize=8)
        clip = " (arrows: clipped)" if extend != "neither" else ""
        fig.suptitle(f"{row['name']}: E − 1 from {lo:+.3f} to {hi:+.3f}{clip}", fontsize=9)
        f = figs.save(fig, f"spheres_{slug(row['name'])}", ["row", row["parameter"], "mean_dev", "min_dev", "max_dev"],
                      csv_rows)
        f.update({"name": row["name"], "exr": row["exr"], "picture": row["png"], "note": row["note"],
                  "parameter": row["parameter"], "values": row["values"], "spp": row["spp"], "res": res,
                  "stats": csv_rows})
        out.append(f)
    return out


def reciprocity_plot(rep, figs):
    rec = rep["reciprocity"]
    # Cases exempt by design (e.g. the phase-function adapter) are listed in the table, not plotted.
    cases = [c for c in rec["cases"] if not c["non_reciprocal_by_design"]]
    names = [c["case"] for c in cases]
    refl = [max(c["reflection_upper"]["max_rel_dev"], c["reflection_lower"]["max_rel_dev"]) for c in cases]
    trans = [c["transmission_adjoint" if c.get("eta_rule") == "adjoint" else "transmission_eta2"]["max_rel_dev"]
             for c in cases]
    fig, ax = plt.subplots(figsize=(8, 0.22 * len(cases) + 1.5), layout="constrained")
    y = np.arange(len(cases))
    floor = 1e-17
    h1 = ax.barh(y - 0.2, np.maximum(refl, floor), height=0.4)
    h2 = ax.barh(y + 0.2, np.maximum(trans, floor), height=0.4)
    h3 = ax.axvline(rec["tolerance"], color="r", ls="--", lw=0.8)
    ax.set_xscale("log")
    ax.set_yticks(y)
    ax.set_yticklabels(names, fontsize=7)
    ax.invert_yaxis()
    ax.set_xlabel(f"max relative deviation |a − b| / max(a, b) (bars start at {floor:g})")
    legend_above(ax, [h1, h2, h3], ["reflection f(v,l) vs f(l,v)", "refraction (η² rule)",
                                     f"tolerance {rec['tolerance']:g}"], ncol=3)
    return figs.save(fig, "reciprocity", ["case", "reflection_max_rel_dev", "transmission_max_rel_dev", "eta_rule",
                                          "plain_symmetry_max_rel_dev"],
                     [[c["case"], r, t, c.get("eta_rule", ""), c["transmission_plain"]["max_rel_dev"]]
                      for c, r, t in zip(cases, refl, trans)])


def chi2_plots(rep, figs):
    ch = rep["chi2"]
    tests = ch["tests"]
    out = {}
    # p-values by name (the same labels as the table below), not by an index.
    fig, ax = plt.subplots(figsize=(8, 0.2 * len(tests) + 1.4), layout="constrained")
    p = np.array([max(t["p_value"], 1e-300) for t in tests])
    y = np.arange(len(tests))
    colors = ["tab:green" if t["passed"] else "tab:red" for t in tests]
    ax.scatter(p, y, c=colors, s=14)
    h = ax.axvline(ch["alpha_per_test"], color="r", ls="--", lw=0.8)
    ax.set_xscale("log")
    ax.set_xlim(min(p.min(), ch["alpha_per_test"]) / 10, 1.5)
    ax.set_yticks(y)
    ax.set_yticklabels([f"{t['case']}, cos θ_v = {t['cos']:g}" for t in tests], fontsize=7)
    ax.invert_yaxis()
    ax.set_xlabel("p-value (green: all sampling checks PASS, red: a failure)")
    ax.grid(alpha=0.3, axis="x")
    legend_above(ax, [h], [f"Šidák-corrected α = {ch['alpha_per_test']:.2e} per test"], ncol=1)
    out["pvalues"] = figs.save(fig, "chi2_pvalues", ["case", "cos", "statistic", "dof", "p_value", "alpha",
                                                      "pdf_integral", "pdf_integral_expected", "verdict"],
                               [[t["case"], t["cos"], t["statistic"], t["dof"], t["p_value"], t["alpha"],
                                 t["pdf_integral"], t["pdf_integral_expected"], t.get("verdict", "")] for t in tests])
    hists = []
    for k, hh in enumerate(ch["histograms"]):
        nt, nphi = hh["theta_bins"], hh["phi_bins"]
        o = np.array(hh["observed"]).reshape(nt, nphi)
        e = np.array(hh["expected"]).reshape(nt, nphi)
        fig, axes = plt.subplots(1, 3, figsize=(13, 3.4), layout="constrained")
        vmax = max(o.max(), e.max(), 1)
        ext = [0, 360, 180, 0]
        im0 = axes[0].imshow(o, aspect="auto", extent=ext, vmin=0, vmax=vmax, cmap="viridis")
        axes[0].set_title("observed samples", fontsize=9)
        axes[1].imshow(e, aspect="auto", extent=ext, vmin=0, vmax=vmax, cmap="viridis")
        axes[1].set_title("expected = N ∫pdf over the bin", fontsize=9)
        fig.colorbar(im0, ax=axes[:2].tolist(), label="samples per bin", shrink=0.9)
        with np.errstate(divide="ignore", invalid="ignore"):
            z = np.where(e > 0, (o - e) / np.sqrt(e), 0)
        zlim = 4
        ext_z = {(False, False): "neither", (True, False): "min", (False, True): "max", (True, True): "both"}[
            (z.min() < -zlim, z.max() > zlim)]
        im2 = axes[2].imshow(z, aspect="auto", extent=ext, vmin=-zlim, vmax=zlim, cmap="RdBu_r")
        axes[2].set_title(f"(obs − exp) / √exp, range {z.min():+.1f} … {z.max():+.1f}", fontsize=9)
        fig.colorbar(im2, ax=axes[2], label="Pearson residual (σ)", extend=ext_z, shrink=0.9)
        for a in axes:
            a.set_xlabel("φ_l (degrees)", fontsize=8)
            a.tick_params(labelsize=7)
        axes[0].set_ylabel("θ_l (degrees)", fontsize=8)
        rows = [[i, j, o[i, j], e[i, j]] for i in range(nt) for j in range(nphi)]
        f = figs.save(fig, f"chi2_hist_{k}", ["theta_bin", "phi_bin", "observed", "expected"], rows)
        f["title"] = f"{hh['case']} at cos θ_v = {hh['cos']:g} (p = {hh['p_value']:.3g})"
        hists.append(f)
    out["histograms"] = hists
    return out


def lut_plots(rep, figs):
    tab = rep["tables"]
    if not tab.get("available"):
        return []
    out = []
    for t in tab["tables"]:
        axes = t["axes"]
        shape = [a["size"] for a in axes]
        name = t.get("label", t["name"])
        unit = f"{TABLE_UNIT.get(t['name'], t['name'])} (albedo, no unit)"
        pic = None
        if "values" not in t:  # renderer layout (warped axes): only the check's nodes are plotted
            pass
        elif len(shape) == 1:
            vals = np.array(t["values"], dtype=float).reshape(shape)
            fig, ax = plt.subplots(figsize=(4.5, 3), layout="constrained")
            x = [axis_coord(axes[0], i) for i in range(shape[0])]
            ax.plot(x, vals, "o-", ms=3)
            ax.set_xlabel(AXIS_WORDS.get(axes[0]["name"], axes[0]["name"]))
            ax.set_ylabel(unit)
            ax.grid(alpha=0.3)
        else:
            vals = np.array(t["values"], dtype=float).reshape(shape)
            idx = [None] if len(shape) == 2 else sorted(set(np.linspace(0, shape[0] - 1, 4).astype(int).tolist()))
            slices = [vals] if len(shape) == 2 else [vals[i] for i in idx]
            titles = [""] if len(shape) == 2 else [f"{AXIS_WORDS.get(axes[0]['name'], axes[0]['name'])} = "
                                                   f"{axis_coord(axes[0], i):.3g}" for i in idx]
            lo, hi = float(vals.min()), float(vals.max())
            vmin, vmax = min(0.0, lo), max(1.0, hi)  # the colour scale covers the true range: nothing clipped
            fig, axs = plt.subplots(1, len(slices), figsize=(3.3 * len(slices) + 1.2, 3.2), squeeze=False,
                                    layout="constrained")
            im = None
            xa, ya = axes[-1], axes[-2]
            for a, s, tt in zip(axs[0], slices, titles):
                im = a.imshow(s, origin="lower", extent=[xa["lo"], xa["hi"], ya["lo"], ya["hi"]], vmin=vmin, vmax=vmax,
                              cmap="magma", aspect="auto")
                a.set_xlabel(AXIS_WORDS.get(xa["name"], xa["name"]), fontsize=8)
                a.set_title(tt, fontsize=8)
                a.tick_params(labelsize=7)
            axs[0, 0].set_ylabel(AXIS_WORDS.get(ya["name"], ya["name"]), fontsize=8)
            cb = fig.colorbar(im, ax=axs[0].tolist())
            cb.set_label(f"{unit}; values {lo:.3g} … {hi:.3g}", fontsize=8)
        if "values" in t:
            fig.suptitle(name, fontsize=9)
            pic = figs.save(fig, f"lut_{slug(name)}", ["flat_index", "value"],
                            [[i, v] for i, v in enumerate(vals.ravel())])
        # Error against the independent reference, with the table's own error estimate beside it.
        cells = t["cells"]
        fig, ax = plt.subplots(figsize=(5.2, 3.6), layout="constrained")
        floor = 1e-12
        h1, = ax.semilogy(np.maximum([c["abs_error"] for c in cells], floor), "o", ms=3)
        h2, = ax.semilogy(np.maximum([c["table_se"] for c in cells], floor), ".", ms=3, color="0.6")
        h3, = ax.semilogy([c["allowed"] for c in cells], "r_")
        ax.set_ylabel("|error| (albedo; relative above 1)", fontsize=8)
        ax.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
        ax.tick_params(labelsize=7)
        ax.set_xlabel(f"checked cell (row of the errors CSV); max |table − reference| {t['max_abs_error']:.2e}",
                      fontsize=8)
        legend_above(ax, [h1, h2, h3], ["|table − reference|", "table's own σ (reported, not used)",
                                        "allowed (fixed)"], ncol=2)
        errf = figs.save(fig, f"lut_error_{slug(name)}",
                         ["index", "x", "table", "table_se", "reference", "reference_err", "abs_error", "allowed"],
                         [[c["index"], c["x"], c["table"], c["table_se"], c["reference"], c["reference_err"],
                           c["abs_error"], c["allowed"]] for c in cells])
        out.append({"name": name, "picture": pic, "error": errf, "max_abs_error": t["max_abs_error"],
                    "max_table_se": t.get("max_table_se", 0.0), "verdict": t.get("verdict", ""),
                    "cells": len(cells), "size": "×".join(str(s) for s in shape), "layout": t.get("layout", ""),
                    "stores": t.get("stores", ""), "reference": t.get("reference", ""),
                    "tolerance": t.get("tolerance", tab.get("tolerance"))})
    return out


def convergence_plot(rep, figs):
    """One panel per component, one colour per case (roughness row); solid: sampled, dashed: eval."""
    conv = rep["convergence"]
    if not conv:
        return None
    comps = []
    for c in conv:
        comp = c.get("component", "")
        if comp not in comps:
            comps.append(comp)
    fig, axes = plt.subplots(1, len(comps), figsize=(4.6 * len(comps) + 2, 3.6), squeeze=False, layout="constrained")
    rows = []
    for ax, comp in zip(axes[0], comps):
        cs = [c for c in conv if c.get("component", "") == comp]
        cmap = plt.get_cmap("viridis")
        for i, c in enumerate(cs):
            col = cmap(i / max(len(cs) - 1, 1) * 0.9)
            n = np.array(c["samples"], dtype=float)
            ax.loglog(n, c["rms_error_sampled"], "o-", ms=3, color=col, label=f"{c['case']}")
            ax.loglog(n, c["rms_error_eval"], "x--", ms=4, color=col)
            for j in range(len(n)):
                rows.append([c["case"], int(n[j]), c["rms_error_sampled"][j], c["rms_error_eval"][j], c["reference"]])
        n = np.array(cs[0]["samples"], dtype=float)
        ax.loglog(n, 0.5 / np.sqrt(n), "k:", label="0.5 N^−1/2")
        if "reference_se" in cs[0]:  # errors cannot be resolved below the reference's own noise
            ax.axhline(max(c["reference_se"] for c in cs), color="0.5", lw=0.8, ls="-.", label="reference σ (largest)")
        ax.set_xlabel("samples (or eval directions) N", fontsize=8)
        ax.set_ylabel(f"RMS error of E(v), cos θ_v = {cs[0]['cos']:g}", fontsize=8)
        ax.set_title(f"{words(comp)}: solid = BSDF-sampled, dashed = eval", fontsize=9)
        ax.grid(alpha=0.3, which="both")
        ax.tick_params(labelsize=7)
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    return figs.save(fig, "convergence", ["case", "samples", "rms_error_sampled", "rms_error_eval", "reference"], rows)


def energy_statement(rep):
    """Where DSPBR itself (the spec's formulas, not our code) loses or gains energy: one row per
    spec statement (the note), with the cases it covers and their range measured with power (the
    views whose conservation band lies within its tolerance); cases without such a view are
    listed apart, never as a property of the spec."""
    groups = {}
    for c in rep["energy"]["cases"]:
        if c["claim"] == "preserving" and c.get("preservation") == "PASS" and c.get("conservation") == "PASS":
            continue
        if c["component"] in ("sheen", "clearcoat") and "lobe" in c["case"]:
            continue  # single lobes on their own are not materials
        g = groups.setdefault(c["note"], {"note": c["note"], "claim": CLAIM_WORDS.get(c["claim"], c["claim"]),
                                          "cases": [], "unmeasured": []})
        if c.get("judged_views", 0) > 0:
            g["cases"].append({"case": c["case"], "min": c["judged_min"], "max": c["judged_max"],
                               "views": c["judged_views"], "of": c["views"]})
        else:
            g["unmeasured"].append(c["case"])
    return list(groups.values())


def not_judged_groups(rep):
    groups = {}
    for v in rep.get("verdicts_not_passed", []):
        if v["status"] == "NOT JUDGED":
            groups.setdefault((v["check"], v.get("reason", "")), []).append(v["what"])
    return [{"check": k[0], "reason": k[1], "items": items} for k, items in groups.items()]


def integrator_study_plot(rep, figs):
    """The table integrators' trade: the committed study (luts/integrator_study.csv) as plotted in
    docs/luts.md."""
    study = rep.get("integrator_study")
    if not study:
        return None
    rows = integrator_plot.read_rows(study["csv"])
    if not rows:
        return None
    fig = integrator_plot.plot(rows)
    header = ["table", "grid", "integrator", "budget", "ms_per_cell", "max_abs_error", "max_stated_error"]
    f = figs.save(fig, "integrator_study", header,
                  [[r["table"], r["grid"], r["integrator"], r["budget"], r["ms_per_cell"], r["max_abs_error"],
                    r["max_stated_error"]] for r in rows])
    f["source"] = study["source"]
    return f


def summary_plot(rep, figs):
    """One page to attach: the banner, the verdict table, what DSPBR itself loses or gains (the
    albedo range of each case measured with power) and the tables' accuracy (worst error of each
    table against its tolerance)."""
    statement = energy_statement(rep)
    cases = [c for s in statement for c in s["cases"]]
    tables = rep["tables"]["tables"] if rep["tables"].get("available") else []
    fig = plt.figure(figsize=(11.0, 8.5), layout="constrained")  # US letter, landscape
    grid = fig.add_gridspec(2, 2, height_ratios=[1.0, 1.25])
    fig.suptitle("\n".join(textwrap.wrap(rep["banner"], 150)), fontsize=8.5, fontweight="bold",
                 color="#060" if all(c["failed"] == 0 for c in rep["summary"]) else "#b00")
    ax = fig.add_subplot(grid[0, :])
    ax.axis("off")
    ax.set_title("Verdicts", fontsize=10, loc="left")
    cells = [[words(c["check"]), c["passed"], c["failed"], c["waived"], c["not_judged"]] for c in rep["summary"]]
    table = ax.table(cellText=cells, colLabels=["check", "PASS", "FAIL", "WAIVED", "NOT JUDGED"], loc="upper left",
                     colWidths=[0.62, 0.09, 0.09, 0.09, 0.11], cellLoc="left")
    table.auto_set_font_size(False)
    table.set_fontsize(8)
    for (row, col), cell in table.get_celld().items():
        if row > 0 and col == 2 and cells[row - 1][2]:
            cell.set_facecolor("#f4c0c0")
        if row > 0 and col == 4 and cells[row - 1][4]:
            cell.set_facecolor("#e8e8e8")
    ax = fig.add_subplot(grid[1, 0])
    ax.set_title("Where DSPBR itself loses or gains energy\n(albedo range of white materials, views judged)",
                 fontsize=9, loc="left")
    y = np.arange(len(cases))
    for i, c in enumerate(cases):
        ax.plot([c["min"], c["max"]], [i, i], lw=4, solid_capstyle="butt",
                color="C3" if c["max"] > 1 + rep["energy"]["tolerances"]["conservation"] else "C0")
    ax.axvline(1.0, color="k", lw=0.8)
    ax.set_yticks(y, [c["case"] for c in cases], fontsize=6.5)
    ax.invert_yaxis()
    ax.set_xlabel("E (blue: loss, red: gain beyond the conservation tolerance)", fontsize=7)
    ax.tick_params(axis="x", labelsize=7)
    ax.grid(axis="x", alpha=0.3)
    ax = fig.add_subplot(grid[1, 1])
    ax.set_title("Tables at the point of use: worst error / tolerance", fontsize=9, loc="left")
    if tables:
        ratio = [max(t["max_abs_error"], 1e-12) / t["tolerance"] for t in tables]
        ax.barh(np.arange(len(tables)), ratio, color=["C3" if r > 1 else "C2" for r in ratio])
        ax.axvline(1.0, color="k", lw=0.8, ls="--")
        ax.set_xscale("log")
        ax.set_yticks(np.arange(len(tables)), [f"{t['label']} (tol {t['tolerance']:g})" for t in tables], fontsize=6.5)
        ax.invert_yaxis()
        ax.tick_params(axis="x", labelsize=7)
        ax.grid(axis="x", alpha=0.3)
    else:
        ax.axis("off")
        ax.text(0, 0.5, "no tables checked", fontsize=8)
    rows = [["verdict", c["check"], c["passed"], c["failed"], c["waived"], c["not_judged"]] for c in rep["summary"]]
    rows += [["energy", c["case"], c["min"], c["max"], c["views"], c["of"]] for c in cases]
    rows += [["table", t["label"], t["max_abs_error"], t["tolerance"], t["verdict"], ""] for t in tables]
    return figs.save(fig, "summary", ["kind", "what", "a", "b", "c", "d"], rows)


SINGLE_FILE_NOTE = ('<p class="warn">This is the single-file copy of the report (report.html, for a release '
                    'attachment): its figures are embedded; the full-size figures, their CSVs, the EXR spheres and '
                    'data/report.json are in the report folder beside index.html.</p>')


def single_file(html, out):
    """The page as one self-contained file: every <img> embedded as a data URI, links to the
    folder's files (full-size PNGs, CSVs, EXRs, report.json) reduced to their text."""
    def embed(m):
        with open(os.path.join(out, m.group(2)), "rb") as f:
            data = base64.b64encode(f.read()).decode("ascii")
        return f'{m.group(1)}"data:image/png;base64,{data}"'

    html = re.sub(r'(<img[^>]*?src=)"((?:plots|images)/[^"]+\.png)"', embed, html)
    html = re.sub(r'<a (?:class="[^"]*" )?href="(?:(?:plots|images|data)/[^"]+|report\.html)">(.*?)</a>', r"\1", html,
                  flags=re.S)
    return html.replace("<h1>", SINGLE_FILE_NOTE + "\n<h1>", 1)


def run_figure_job(name, out):
    with open(os.path.join(out, "data", "report.json")) as f:
        rep = json.load(f)
    figs = Figures(out)
    if name == "spheres":
        return sphere_plots(rep, figs, out)
    if name.startswith("furnace:"):
        return furnace_plots(rep, figs, int(name[-1]))
    if name == "shader_furnace":  # the shader library's section
        return furnace_plots(rep, figs, energy=rep["shader_library"]["energy"], name=name)
    return {"furnace": furnace_plots, "luts": lut_plots, "chi2": chi2_plots, "reciprocity": reciprocity_plot,
            "convergence": convergence_plot, "integrators": integrator_study_plot, "summary": summary_plot}[name](rep, figs)


def read_report(report_dir, prog):
    """REPORT/data/report.json as written by `dspbr validate`, or None after a one-line message on
    stderr naming the file and what is wrong (prog: the script's name)."""
    path = os.path.join(report_dir, "data", "report.json")
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        print(f"{prog}: cannot read {path}: {e}", file=sys.stderr)
        return None


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    out = sys.argv[1]
    rep = read_report(out, "make_report.py")
    if rep is None:
        return 1
    # The figure groups are independent: drawn by two processes (most costly first, the furnace
    # plots in two halves). The integrator study (committed data, the same in every run) and the
    # shader library's furnace figures only in the full run's report: the quick run stays within
    # seconds (it shows the library's furnace tables alone).
    jobs = ["furnace:0", "furnace:1", "luts", "chi2", "spheres", "summary", "convergence", "reciprocity"]
    if rep.get("mode") != "quick":
        jobs.insert(2, "integrators")
        if "shader_library" in rep:
            jobs.insert(2, "shader_furnace")
    with ProcessPoolExecutor(max_workers=2) as pool:
        futures = {k: pool.submit(run_figure_job, k, out) for k in jobs}
        ctx = {k: f.result() for k, f in futures.items()}
    # The furnace halves in the components' order.
    halves = [ctx.pop("furnace:0"), ctx.pop("furnace:1")]
    ctx["furnace"] = [f for pair in itertools.zip_longest(*halves) for f in pair if f is not None]
    ctx.setdefault("integrators", None)
    if "shader_library" in rep and "shader_furnace" not in ctx:  # the quick run: the tables without figures
        ctx["shader_furnace"] = furnace_plots(rep, None, energy=rep["shader_library"]["energy"], name="shader_furnace")
    ctx.setdefault("shader_furnace", [])
    ctx.update({
        "rep": rep,
        "statement": energy_statement(rep),
        "not_judged": not_judged_groups(rep),
        "failed": sum(c["failed"] for c in rep["summary"]),
        "claim_words": CLAIM_WORDS,
    })
    env = Environment(loader=FileSystemLoader(os.path.join(HERE, "templates")),
                      autoescape=select_autoescape(["html"]))
    env.filters["g"] = lambda x, d=4: f"{x:.{d}g}" if isinstance(x, (int, float)) else x
    env.filters["words"] = words
    env.filters["word"] = lambda s: {"PASS": "pass", "FAIL": "fail", "WAIVED": "waived", "NOT JUDGED": "nj"}.get(s, "")
    html = env.get_template("index.html.j2").render(**ctx)
    for name, text in (("index.html", html), ("report.html", single_file(html, out))):
        tmp = os.path.join(out, f".{name}.tmp")
        with open(tmp, "w") as f:
            f.write(text)
        os.replace(tmp, os.path.join(out, name))
    return 0


if __name__ == "__main__":
    sys.exit(main())
