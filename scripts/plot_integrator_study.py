#!/usr/bin/python3
"""Log-log plot of the table integrators' trade (docs/design/luts.md, "Speed"): max error against the
reference, against the time per cell, one line per integrator and table.

Runs `dspbr lut --bench-integrators --bench-csv` (or reads a CSV it wrote, e.g. the committed
luts/integrator_study.csv) and writes a PNG.

Usage: /usr/bin/python3 scripts/plot_integrator_study.py [--dspbr build/dspbr | --csv FILE]
                                                        [--out docs/img/integrator_study.png]
                                                        [-- extra dspbr lut options]
"""
import argparse
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "report"))
import integrator_plot  # noqa: E402  (scripts/report/integrator_plot.py, shared with the report)


def run_bench(dspbr, extra):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "study.csv")
        subprocess.run([dspbr, "lut", "--bench-integrators", "--bench-csv", path] + extra, check=True,
                       stdout=subprocess.DEVNULL)
        with open(path) as f:
            return f.read()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dspbr", default="build/dspbr", help="the dspbr binary to run (default: build/dspbr)")
    ap.add_argument("--csv", help="read this CSV (from --bench-csv) instead of running dspbr")
    ap.add_argument("--out", default="docs/img/integrator_study.png", help="the PNG to write")
    ap.add_argument("extra", nargs="*", help="extra `dspbr lut` options, after --")
    a = ap.parse_args()
    if a.csv:
        with open(a.csv) as f:
            text = f.read()
    else:
        text = run_bench(a.dspbr, a.extra)
    rows = integrator_plot.read_rows(text)
    if not rows:
        sys.exit(f"{a.csv or a.dspbr}: no integrator rows")
    fig = integrator_plot.plot(rows)
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    fig.savefig(a.out, dpi=110)
    print(f"wrote {a.out} ({len(rows)} rows)")


if __name__ == "__main__":
    main()
