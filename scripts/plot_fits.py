#!/usr/bin/python3
"""Plots of the Ceres fits for docs/fits.md, read from fits/*.json (written by `dspbr fit`).

Usage: /usr/bin/python3 scripts/plot_fits.py [--fits fits] [--out docs/img]
"""
import argparse
import json
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

MODELS = [("ck17", "Conty Estevez & Kulla 2017"), ("spec", "DSPBR 2025x spec"),
          ("ours_spec_form", "spec form, refitted"), ("ours_rich", "ours (richer form)")]


def load(folder, name):
    with open(os.path.join(folder, name + ".json")) as f:
        return json.load(f)


def plot_lambda(sl, out):
    curves = sl["error"]["curves"]
    fig, axes = plt.subplots(1, len(curves), figsize=(4 * len(curves), 3.4), sharey=True)
    for ax, c in zip(axes, curves):
        mu = np.array(c["cos_theta"])
        ex = np.array(c["lambda"]["exact"])
        for key, label in MODELS:
            ax.plot(mu, np.array(c["lambda"][key]) / ex - 1, label=label)
        ax.set_title("alpha_b = %.4g" % c["alpha_b"])
        ax.set_xlabel("cos theta")
        ax.axhline(0, color="k", lw=0.5)
        ax.set_ylim(-1, 1.5)
    axes[0].set_ylabel("Lambda / exact - 1")
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fit_sheen_lambda_error.png"), dpi=90)
    plt.close(fig)


def plot_sheen_albedo(sl, out):
    rows = sl["error"]["albedo"]
    fig, axes = plt.subplots(1, len(rows), figsize=(4 * len(rows), 3.4), sharey=True)
    for ax, r in zip(axes, rows):
        mu = np.array(r["cos_theta"])
        ax.plot(mu, r["E_b"]["exact"], "k-", lw=2, label="exact Lambda")
        for key, label in MODELS:
            ax.plot(mu, r["E_b"][key], label=label)
        ax.set_title("alpha_b = %.4g" % r["alpha_b"])
        ax.set_xlabel("cos theta")
        ax.axhline(1, color="r", lw=0.5)
    axes[0].set_ylabel("sheen albedo E_b (white furnace)")
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fit_sheen_albedo.png"), dpi=90)
    plt.close(fig)


def plot_maps(al, out):
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, (key, ylab) in zip(axes, [("ggx_E", "roughness"), ("sheen_E", "alpha_b")]):
        m = al["error"]["maps"][key]
        y = np.array(m[ylab])
        mu = np.array(m["cos_theta"])
        err = np.array(m["error"]).reshape(len(y), len(mu))
        order = np.argsort(y)
        lim = np.abs(err).max()
        im = ax.pcolormesh(mu, y[order], err[order], cmap="RdBu_r", vmin=-lim, vmax=lim, shading="nearest")
        if ylab == "alpha_b":
            ax.set_yscale("log")
        ax.set_xlabel("cos theta")
        ax.set_ylabel(ylab)
        ax.set_title("%s: fit - exact (max %.1e)" % (key, lim))
        fig.colorbar(im, ax=ax)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fit_albedo_error.png"), dpi=90)
    plt.close(fig)


def plot_flakes(fl, out):
    rows = fl["per_r_f"]
    rf = np.array([r["r_f"] for r in rows])
    req = np.array([r["r_eq"] for r in rows])
    a0, a1, b1 = fl["coefficients"]
    x = np.linspace(rf.min(), rf.max(), 200)
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    axes[0].plot(rf, req, "o", label="per-r_f Ceres fit")
    axes[0].plot(x, np.sqrt(x) * (a0 + a1 * x) / (1 + b1 * x), label="r_eq(r_f) formula")
    axes[0].plot(x, x, ":", label="r_eq = r_f")
    axes[0].set_xlabel("flake roughness r_f")
    axes[0].set_ylabel("equivalent GGX roughness r_eq")
    axes[0].legend(fontsize=8)
    axes[1].plot(rf, [r["lobe_rel_l2_error"] for r in rows], "o-", label="lobe shape, rel. L2")
    for k in range(len(rows[0]["views"])):
        cv = rows[0]["views"][k]["cos_view"]
        axes[1].plot(rf, [r["views"][k]["albedo_aggregate"] for r in rows], "--",
                     label="aggregate albedo, cos_v = %.2f" % cv)
    axes[1].set_xlabel("flake roughness r_f")
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fit_flakes.png"), dpi=90)
    plt.close(fig)


def plot_flake_lobes(fl, out):
    slices = fl["lobe_slices"]
    rfs = sorted({s["r_f"] for s in slices})
    views = sorted({s["view_deg"] for s in slices})
    fig, axes = plt.subplots(len(rfs), len(views), figsize=(11, 8))
    for s in slices:
        ax = axes[rfs.index(s["r_f"])][views.index(s["view_deg"])]
        t = np.degrees(np.array(s["theta_offset"]))
        agg, cone, ggx = (np.array(s[k]) for k in ("aggregate", "cone_lobe", "ggx"))
        scale = np.dot(agg, ggx) / max(np.dot(ggx, ggx), 1e-30)  # best scale of the GGX lobe on the slice
        ax.plot(t, agg, "k-", lw=2, label="aggregate (quadrature)")
        ax.plot(t, cone, "r--", label="cone lobe (model)")
        ax.plot(t, scale * ggx, "b:", label="GGX r_eq, best scale")
        ax.set_title("r_f = %.2f, view %g deg" % (s["r_f"], s["view_deg"]), fontsize=9)
        ax.set_xlabel("theta_l - theta_mirror (deg)", fontsize=8)
        ax.tick_params(labelsize=7)
    axes[0][0].legend(fontsize=7)
    fig.suptitle("far-field flake lobe f cos(theta_l) in the plane of incidence")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fit_flake_lobes.png"), dpi=80)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--fits", default="fits")
    ap.add_argument("--out", default="docs/img")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    plot_lambda(load(a.fits, "sheen_lambda"), a.out)
    plot_sheen_albedo(load(a.fits, "sheen_lambda"), a.out)
    plot_maps(load(a.fits, "albedo"), a.out)
    plot_flakes(load(a.fits, "flake_roughness"), a.out)
    plot_flake_lobes(load(a.fits, "flake_roughness"), a.out)


if __name__ == "__main__":
    main()
