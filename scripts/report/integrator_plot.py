"""The log-log plot of the table integrators' trade (docs/design/luts.md, "Speed"), shared by
scripts/plot_integrator_study.py (docs/img/integrator_study.png) and the validation report."""
import csv
import io

import matplotlib.pyplot as plt

# A measured error of 0 (bit-equal to the reference) is drawn at this floor.
ERROR_FLOOR = 1e-12
STYLES = {"qmc": "-o", "mc": "--s", "quad": "-^"}


def read_rows(text):
    """The measured rows of a `dspbr lut --bench-csv` file (the reference rows left out)."""
    return [r for r in csv.DictReader(io.StringIO(text)) if r["reference"] == "0"]


def plot(rows):
    """One panel per table: max |error| against ms per cell, one line per integrator."""
    tables = list(dict.fromkeys(r["table"] for r in rows))
    cols = min(5, len(tables))
    nrows = (len(tables) + cols - 1) // cols
    fig, axes = plt.subplots(nrows, cols, figsize=(3.2 * cols, 3.0 * nrows), sharex=True, sharey=True,
                             squeeze=False, layout="constrained")
    for ax, table in zip(axes.flat, tables):
        for integrator, style in STYLES.items():
            pts = sorted((float(r["ms_per_cell"]), max(float(r["max_abs_error"]), ERROR_FLOOR))
                         for r in rows if r["table"] == table and r["integrator"] == integrator)
            if pts:
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
    return fig
