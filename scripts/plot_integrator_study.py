#!/usr/bin/python3
"""Log-log plot of the table integrators' trade (docs/luts.md, "Speed"): max error against the
reference, against the time per cell, one line per integrator and table.

Runs `dspbr lut --bench-integrators --bench-csv` (or reads a CSV it wrote) and writes a PNG.

Usage: /usr/bin/python3 scripts/plot_integrator_study.py [--dspbr build/dspbr | --csv FILE]
                                                        [--out docs/img/integrator_study.png]
                                                        [-- extra dspbr lut options]
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The error floor of the plot: a measured error of 0 (bit-equal to the reference) is drawn here.
ERROR_FLOOR = 1e-12
STYLES = {"qmc": "-o", "mc": "--s", "quad": "-^"}


def run_bench(dspbr, extra):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "study.csv")
        subprocess.run([dspbr, "lut", "--bench-integrators", "--bench-csv", path] + extra, check=True,
                       stdout=subprocess.DEVNULL)
        return read_rows(path)


def read_rows(path):
    with open(path, newline="") as f:
        return [r for r in csv.DictReader(f) if r["reference"] == "0"]


def plot(rows, out):
    tables = list(dict.fromkeys(r["table"] for r in rows))
    cols = 5 if len(tables) > 5 else len(tables)
    nrows = (len(tables) + cols - 1) // cols
    fig, axes = plt.subplots(nrows, cols, figsize=(3.2 * cols, 3.0 * nrows), sharex=True, sharey=True,
                             squeeze=False)
    for ax, table in zip(axes.flat, tables):
        for integrator, style in STYLES.items():
            pts = [(float(r["ms_per_cell"]), max(float(r["max_abs_error"]), ERROR_FLOOR))
                   for r in rows if r["table"] == table and r["integrator"] == integrator]
            if pts:
                pts.sort()
                ax.loglog([p[0] for p in pts], [p[1] for p in pts], style, label=integrator, markersize=4)
        ax.axhline(1e-6, color="grey", lw=0.6, ls=":")
        ax.set_title(table, fontsize=9)
        ax.grid(True, which="major", lw=0.3)
    for ax in axes.flat[len(tables):]:
        ax.axis("off")
    for ax in axes[-1]:
        ax.set_xlabel("ms per cell")
    for ax in axes[:, 0]:
        ax.set_ylabel("max |error|")
    axes.flat[0].legend(fontsize=8)
    fig.suptitle("Table integrators: error against time per cell (dotted: 1e-6)", fontsize=10)
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fig.savefig(out, dpi=110)
    print(f"wrote {out} ({len(rows)} rows, {len(tables)} tables)")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dspbr", default="build/dspbr", help="the dspbr binary to run (default: build/dspbr)")
    ap.add_argument("--csv", help="read this CSV (from --bench-csv) instead of running dspbr")
    ap.add_argument("--out", default="docs/img/integrator_study.png", help="the PNG to write")
    ap.add_argument("extra", nargs="*", help="extra `dspbr lut` options, after --")
    a = ap.parse_args()
    rows = read_rows(a.csv) if a.csv else run_bench(a.dspbr, a.extra)
    if not rows:
        sys.exit(f"{a.csv or a.dspbr}: no integrator rows")
    plot(rows, a.out)


if __name__ == "__main__":
    main()
