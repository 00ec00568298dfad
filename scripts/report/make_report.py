#!/usr/bin/env python3
"""Builds the validation report DIR/index.html (+ DIR/plots/*.png and *.csv) from the data
DIR/data/report.json written by `dspbr validate`. Run with /usr/bin/python3 (numpy, matplotlib,
jinja2). Every figure is written as PNG together with a CSV of the numbers it shows.

usage: make_report.py DIR
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from jinja2 import Environment, FileSystemLoader, select_autoescape  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def slug(s):
    return "".join(c if c.isalnum() else "_" for c in s).strip("_")


class Figures:
    def __init__(self, out):
        self.out = out
        os.makedirs(os.path.join(out, "plots"), exist_ok=True)

    def save(self, fig, name, header, rows):
        png = f"plots/{name}.png"
        csv_path = f"plots/{name}.csv"
        fig.savefig(os.path.join(self.out, png), dpi=110, bbox_inches="tight")
        plt.close(fig)
        with open(os.path.join(self.out, csv_path), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(header)
            w.writerows(rows)
        return {"png": png, "csv": csv_path}


def furnace_plots(rep, figs):
    energy = rep["energy"]
    tol = energy["tolerances"]
    rows_by_case = {}
    for r in energy["rows"]:
        rows_by_case.setdefault(r["case"], []).append(r)
    cases = energy["cases"]
    groups = {}
    for c in cases:
        groups.setdefault(c["component"], []).append(c)
    out = []
    for comp, cs in groups.items():
        fig, ax = plt.subplots(figsize=(7.5, 4))
        csv_rows = []
        for c in cs:
            rs = sorted(rows_by_case[c["case"]], key=lambda r: r["cos"])
            x = np.array([r["cos"] for r in rs])
            y = np.array([r["sampled"][1] for r in rs])
            e = np.array([r["sampled_se"][1] for r in rs])
            ye = np.array([r["eval"][1] for r in rs])
            line = ax.errorbar(x, y, yerr=4 * e, marker="o", ms=3, capsize=2, label=c["case"])
            ax.plot(x, ye, "x", color=line[0].get_color(), ms=5)
            for r in rs:
                csv_rows.append([c["case"], r["cos"], *r["sampled"], *r["sampled_se"], *r["eval"], *r["eval_se"],
                                 r["invalid_fraction"], r["conserving"], r["preserving"], r["estimators_agree"]])
        ax.axhline(1.0, color="k", lw=0.8)
        ax.axhline(1.0 + tol["conservation"], color="r", lw=0.6, ls="--")
        if any(c["claim"] == "preserving" for c in cs):
            ax.axhline(1.0 - tol["preservation"], color="b", lw=0.6, ls="--")
        ax.set_xlabel("cos θ_v (negative: viewer inside)")
        ax.set_ylabel("directional albedo E(v)")
        ax.set_title(f"White furnace: {comp}  (o: BSDF-sampled ±4σ, x: cosine-weighted eval)")
        ax.legend(fontsize=7, loc="best")
        ax.grid(alpha=0.3)
        f = figs.save(fig, f"furnace_{slug(comp)}",
                      ["case", "cos", "sampled_r", "sampled_g", "sampled_b", "se_r", "se_g", "se_b", "eval_r", "eval_g",
                       "eval_b", "eval_se_r", "eval_se_g", "eval_se_b", "invalid_fraction", "conserving", "preserving",
                       "estimators_agree"], csv_rows)
        f["component"] = comp
        f["cases"] = cs
        out.append(f)
    return out


def sphere_plots(rep, figs):
    out = []
    for row in rep["furnace_images"]:
        n = len(row["values"])
        res = row["res"]
        fig, axes = plt.subplots(1, n, figsize=(2.1 * n + 1, 2.4), squeeze=False)
        csv_rows = []
        lim = 0.2
        im = None
        for k, (val, alb) in enumerate(zip(row["values"], row["albedo_green"])):
            a = np.array(alb, dtype=float).reshape(res, res)
            yy, xx = np.mgrid[0:res, 0:res]
            inside = ((xx + 0.5) / res * 2 - 1) ** 2 + (1 - (yy + 0.5) / res * 2) ** 2 < 1
            dev = np.where(inside, a - 1.0, np.nan)
            im = axes[0, k].imshow(dev, cmap="RdBu_r", vmin=-lim, vmax=lim)
            axes[0, k].set_title(f"{val:g}", fontsize=8)
            axes[0, k].axis("off")
            d = a[inside] - 1.0
            csv_rows.append([row["name"], val, float(d.mean()), float(d.min()), float(d.max())])
        fig.colorbar(im, ax=axes[0, :].tolist(), shrink=0.8, label="E − 1 (red: gain, blue: loss)")
        fig.suptitle(f"Furnace spheres, deviation from 1: {row['name']} ({row['parameter']} left to right)", fontsize=9)
        f = figs.save(fig, f"spheres_{slug(row['name'])}", ["row", row["parameter"], "mean_dev", "min_dev", "max_dev"],
                      csv_rows)
        f.update({"name": row["name"], "picture": row["png"], "exr": row["exr"], "note": row["note"],
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
    fig, ax = plt.subplots(figsize=(8, 0.22 * len(cases) + 1.5))
    y = np.arange(len(cases))
    floor = 1e-17
    ax.barh(y - 0.2, np.maximum(refl, floor), height=0.4, label="reflection f(v,l) vs f(l,v)")
    ax.barh(y + 0.2, np.maximum(trans, floor), height=0.4, label="refraction (η² rule)")
    ax.axvline(rec["tolerance"], color="r", ls="--", lw=0.8, label="tolerance")
    ax.set_xscale("log")
    ax.set_yticks(y)
    ax.set_yticklabels(names, fontsize=7)
    ax.invert_yaxis()
    ax.set_xlabel("max relative deviation")
    ax.legend(fontsize=7)
    return figs.save(fig, "reciprocity", ["case", "reflection_max_rel_dev", "transmission_max_rel_dev", "eta_rule",
                                          "plain_symmetry_max_rel_dev"],
                     [[c["case"], r, t, c.get("eta_rule", ""), c["transmission_plain"]["max_rel_dev"]]
                      for c, r, t in zip(cases, refl, trans)])


def chi2_plots(rep, figs):
    ch = rep["chi2"]
    tests = ch["tests"]
    out = {}
    fig, ax = plt.subplots(figsize=(8, 3.5))
    p = np.array([max(t["p_value"], 1e-300) for t in tests])
    colors = ["tab:green" if t["passed"] else "tab:red" for t in tests]
    ax.scatter(np.arange(len(tests)), p, c=colors, s=12)
    ax.axhline(ch["alpha_per_test"], color="r", ls="--", lw=0.8, label=f"Šidák α = {ch['alpha_per_test']:.2e}")
    ax.set_yscale("log")
    ax.set_xlabel("test (case × incidence, see table)")
    ax.set_ylabel("p-value")
    ax.legend(fontsize=7)
    out["pvalues"] = figs.save(fig, "chi2_pvalues", ["case", "cos", "statistic", "dof", "p_value", "alpha",
                                                      "pdf_integral", "pdf_integral_expected", "passed"],
                               [[t["case"], t["cos"], t["statistic"], t["dof"], t["p_value"], t["alpha"],
                                 t["pdf_integral"], t["pdf_integral_expected"], t["passed"]] for t in tests])
    hists = []
    for k, h in enumerate(ch["histograms"]):
        nt, nphi = h["theta_bins"], h["phi_bins"]
        o = np.array(h["observed"]).reshape(nt, nphi)
        e = np.array(h["expected"]).reshape(nt, nphi)
        fig, axes = plt.subplots(1, 3, figsize=(11, 2.6))
        vmax = max(o.max(), e.max(), 1)
        ext = [0, 360, 180, 0]
        axes[0].imshow(o, aspect="auto", extent=ext, vmin=0, vmax=vmax, cmap="viridis")
        axes[0].set_title("observed", fontsize=8)
        im1 = axes[1].imshow(e, aspect="auto", extent=ext, vmin=0, vmax=vmax, cmap="viridis")
        axes[1].set_title("expected (∫pdf)", fontsize=8)
        fig.colorbar(im1, ax=axes[1])
        with np.errstate(divide="ignore", invalid="ignore"):
            z = np.where(e > 0, (o - e) / np.sqrt(e), 0)
        im2 = axes[2].imshow(z, aspect="auto", extent=ext, vmin=-4, vmax=4, cmap="RdBu_r")
        axes[2].set_title("(obs − exp) / √exp", fontsize=8)
        fig.colorbar(im2, ax=axes[2])
        for a in axes:
            a.set_xlabel("φ (deg)")
            a.set_ylabel("θ (deg)")
        fig.suptitle(f"{h['case']}, cos θ_v = {h['cos']:g}, p = {h['p_value']:.3g}", fontsize=9)
        rows = [[i, j, o[i, j], e[i, j]] for i in range(nt) for j in range(nphi)]
        f = figs.save(fig, f"chi2_hist_{k}", ["theta_bin", "phi_bin", "observed", "expected"], rows)
        f["title"] = f"{h['case']} at cos θ_v = {h['cos']:g}"
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
        vals = np.array(t["values"], dtype=float)
        shape = [a["size"] for a in axes]
        vals = vals.reshape(shape)
        name = t["name"]
        if len(shape) == 1:
            fig, ax = plt.subplots(figsize=(4.5, 3))
            x = [(i + 0.5) / shape[0] if axes[0]["kind"] == "cell_centred" else i / (shape[0] - 1) for i in range(shape[0])]
            ax.plot(x, vals, "o-", ms=3)
            ax.set_xlabel(axes[0]["name"])
            ax.set_ylabel(name)
            ax.grid(alpha=0.3)
        else:
            slices = [vals] if len(shape) == 2 else [vals[i] for i in np.linspace(0, shape[0] - 1, 4).astype(int)]
            titles = [""] if len(shape) == 2 else [f"{axes[0]['name']} index {i}" for i in
                                                    np.linspace(0, shape[0] - 1, 4).astype(int)]
            fig, axs = plt.subplots(1, len(slices), figsize=(3.6 * len(slices) + 1, 3.2), squeeze=False)
            im = None
            for a, s, tt in zip(axs[0], slices, titles):
                im = a.imshow(s, origin="lower", extent=[0, 1, 0, 1], vmin=0, vmax=1, cmap="magma")
                a.set_xlabel(axes[-1]["name"])
                a.set_ylabel(axes[-2]["name"])
                a.set_title(tt, fontsize=8)
            fig.colorbar(im, ax=axs[0].tolist(), label=name)
        fig.suptitle(name, fontsize=9)
        pic = figs.save(fig, f"lut_{slug(name)}", ["flat_index", "value"], [[i, v] for i, v in enumerate(vals.ravel())])
        # Error against the independent reference.
        cells = t["cells"]
        fig, ax = plt.subplots(figsize=(4.5, 3))
        err = [c["abs_error"] for c in cells]
        allowed = [c["allowed"] for c in cells]
        ax.semilogy(np.maximum(err, 1e-12), "o", ms=3, label="|table − reference|")
        ax.semilogy(allowed, "r_", label="allowed")
        ax.set_xlabel("checked cell")
        ax.set_title(f"{name}: max error {t['max_abs_error']:.2e}", fontsize=9)
        ax.legend(fontsize=7)
        errf = figs.save(fig, f"lut_error_{slug(name)}",
                         ["index", "x", "table", "table_se", "reference", "reference_err", "abs_error", "allowed"],
                         [[c["index"], c["x"], c["table"], c["table_se"], c["reference"], c["reference_err"],
                           c["abs_error"], c["allowed"]] for c in cells])
        out.append({"name": name, "picture": pic, "error": errf, "max_abs_error": t["max_abs_error"],
                    "passed": t["passed"], "cells": len(cells)})
    return out


def convergence_plot(rep, figs):
    conv = rep["convergence"]
    if not conv:
        return None
    fig, ax = plt.subplots(figsize=(6, 4))
    rows = []
    for c in conv:
        n = np.array(c["samples"], dtype=float)
        l1 = ax.loglog(n, np.maximum(c["rms_error_sampled"], 1e-12), "o-", ms=3, label=f"{c['case']} (sampled)")
        ax.loglog(n, np.maximum(c["rms_error_eval"], 1e-12), "x--", ms=4, color=l1[0].get_color(),
                  label=f"{c['case']} (eval)")
        for i in range(len(n)):
            rows.append([c["case"], int(n[i]), c["rms_error_sampled"][i], c["rms_error_eval"][i], c["reference"]])
    n = np.array(conv[0]["samples"], dtype=float)
    ax.loglog(n, 0.5 / np.sqrt(n), "k:", label="∝ N^−1/2")
    ax.set_xlabel("samples N")
    ax.set_ylabel("RMS error of E(v) at cos θ_v = 0.5")
    ax.legend(fontsize=6)
    ax.grid(alpha=0.3, which="both")
    return figs.save(fig, "convergence", ["case", "samples", "rms_error_sampled", "rms_error_eval", "reference"], rows)


def energy_statement(rep):
    """Where DSPBR itself (the spec's formulas, not our code) loses or gains energy, with numbers."""
    out = []
    for c in rep["energy"]["cases"]:
        if c["claim"] == "preserving" and c["preserving"] and c["conserving"]:
            continue
        if c["component"] in ("sheen", "clearcoat") and "lobe" in c["case"]:
            continue  # single lobes on their own are not materials
        out.append({"case": c["case"], "claim": c["claim"], "min": c["min"], "max": c["max"], "note": c["note"]})
    return out


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    out = sys.argv[1]
    path = os.path.join(out, "data", "report.json")
    try:
        with open(path) as f:
            rep = json.load(f)
    except (OSError, ValueError) as e:
        print(f"make_report.py: cannot read {path}: {e}", file=sys.stderr)
        return 1
    figs = Figures(out)
    ctx = {
        "rep": rep,
        "furnace": furnace_plots(rep, figs),
        "spheres": sphere_plots(rep, figs),
        "reciprocity": reciprocity_plot(rep, figs),
        "chi2": chi2_plots(rep, figs),
        "luts": lut_plots(rep, figs),
        "convergence": convergence_plot(rep, figs),
        "statement": energy_statement(rep),
        "failed": sum(c["total"] - c["passed"] for c in rep["summary"]),
    }
    env = Environment(loader=FileSystemLoader(os.path.join(HERE, "templates")),
                      autoescape=select_autoescape(["html"]))
    env.filters["g"] = lambda x, d=4: f"{x:.{d}g}" if isinstance(x, (int, float)) else x
    html = env.get_template("index.html.j2").render(**ctx)
    tmp = os.path.join(out, ".index.html.tmp")
    with open(tmp, "w") as f:
        f.write(html)
    os.replace(tmp, os.path.join(out, "index.html"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
