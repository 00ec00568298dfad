#!/usr/bin/env python3
"""Builds the conformance report DIR/index.html and DIR/plots/*.png from DIR/report.json written
by `dspbr conformance check` (docs/conformance.md). Run with /usr/bin/python3 (numpy, matplotlib,
jinja2). Plots: per group, the distribution of the error of f cos over its tolerance (log scale;
1 is the pass limit) and of the relative error of f cos.

usage: conformance_report.py DIR
"""
import signal

# SIGINT ends the script at once and without a traceback (SIGTERM does by default): dspbr,
# interrupted with it, says so in one line and discards the report folder (docs/limits.md).
signal.signal(signal.SIGINT, signal.SIG_DFL)
import json
import math
import os
import sys
import warnings

import matplotlib

# A label's character that the font lacks (an emoji in a group name) is drawn as a box; matplotlib's
# warning about it would only repeat the name on stderr.
warnings.filterwarnings("ignore", message="Glyph .* missing from")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from jinja2 import Environment, select_autoescape  # noqa: E402

PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>DSPBR conformance: {{ r.verdict }}</title>
<style>
body { font-family: sans-serif; margin: 2em; max-width: 80em; }
table { border-collapse: collapse; margin: 1em 0; }
td, th { border: 1px solid #bbb; padding: 0.2em 0.6em; text-align: left; font-size: 90%; }
.PASS { color: #060; font-weight: bold; } .FAIL { color: #b00; font-weight: bold; }
.NJ { color: #777; } code { font-size: 85%; }
</style></head><body>
<h1>DSPBR conformance: <span class="{{ r.verdict }}">{{ r.verdict }}</span></h1>
<p>{{ r.summary.passed }} of {{ r.summary.vectors - r.summary.not_supplied }} judged vectors pass{% if r.summary.not_supplied %}; {{ r.summary.not_supplied }} of {{ r.summary.vectors }} NOT SUPPLIED (no quantity in the results){% endif %}. Vectors <code>{{ r.provenance.vectors }}</code>,
results <code>{{ r.provenance.results }}</code>; {{ r.provenance.dspbr }}.
A value passes when, per channel, |result − expected| ≤ abs + rel · |expected| (the vector's tolerance);
the ratio is the error over that bound (≤ 1 passes).</p>

<h2>Quantities</h2>
<table><tr><th>quantity</th><th>judged</th><th>PASS</th><th>FAIL</th><th>NOT JUDGED</th></tr>
{% for name, q in r.quantities.items() %}<tr><td>{{ name }}</td><td>{{ q.judged }}</td><td>{{ q.passed }}</td>
<td>{{ q.failed }}</td><td class="NJ">{{ q.not_judged }}{% if q.not_judged %} (not supplied){% endif %}</td></tr>
{% endfor %}</table>

{% if r.diagnosis %}<h2>Likely causes (docs/conformance.md, "Diagnosis")</h2>
<p>Of the {{ r.diagnosis.failing }} vectors whose f cos or emission fails: each cause's reference explains
some (within their tolerances) and contradicts passing ones.</p>
{% if r.diagnosis.causes %}<table><tr><th>cause</th><th>explains</th><th>contradicts</th><th>evidence</th><th>remedy</th></tr>
{% for c in r.diagnosis.causes %}<tr><td><code>{{ c.cause }}</code></td><td>{{ c.explains }}</td><td>{{ c.contradicts }}</td>
<td>{{ c.evidence }}</td><td>{{ c.remedy }}</td></tr>
{% endfor %}</table>
<table><tr><th>group</th><th>failing</th><th>first cause (explains, contradicts)</th></tr>
{% for g in r.groups %}{% if g.diagnosis %}<tr><td>{{ g.name }}</td><td>{{ g.diagnosis.failing }}</td>
<td>{% if g.diagnosis.causes %}<code>{{ g.diagnosis.causes[0].cause }}</code> ({{ g.diagnosis.causes[0].explains }}, {{ g.diagnosis.causes[0].contradicts }}){% else %}none of the vocabulary{% endif %}</td></tr>{% endif %}
{% endfor %}</table>
{% else %}<p>No cause of the vocabulary explains them.</p>{% endif %}
{% endif %}
<h2>Verdict per group (the component a set of vectors tests)</h2>
<table><tr><th>group</th><th>verdict</th><th>vectors</th><th>PASS</th><th>FAIL</th><th>NOT SUPPLIED</th><th>worst ratio</th><th>worst vector</th></tr>
{% for g in r.groups %}<tr><td>{{ g.name }}</td><td class="{{ g.verdict }}">{{ g.verdict }}</td><td>{{ g.vectors }}</td>
<td>{{ g.passed }}</td><td>{{ g.failed }}</td><td class="NJ">{{ g.not_supplied }}</td><td>{{ "%.3g"|format(g.worst_ratio) }}</td><td><code>{{ g.worst_id }}</code></td></tr>
{% endfor %}</table>

<h2>Per active component (every vector whose material has it)</h2>
<table><tr><th>component</th><th>verdict</th><th>vectors</th><th>PASS</th><th>FAIL</th><th>NOT SUPPLIED</th><th>worst ratio</th><th>worst vector</th></tr>
{% for g in r.components %}<tr><td>{{ g.name }}</td><td class="{{ g.verdict }}">{{ g.verdict }}</td><td>{{ g.vectors }}</td>
<td>{{ g.passed }}</td><td>{{ g.failed }}</td><td class="NJ">{{ g.not_supplied }}</td><td>{{ "%.3g"|format(g.worst_ratio) }}</td><td><code>{{ g.worst_id }}</code></td></tr>
{% endfor %}</table>

<h2>Error distributions</h2>
<p><img src="plots/ratio_by_group.png" alt="error over tolerance per group" width="900"></p>
<p><img src="plots/relative_error_by_group.png" alt="relative error of f cos per group" width="900"></p>

<h2>The worst {{ r.worst|length }} vectors</h2>
<table><tr><th>id</th><th>verdict</th><th>ratio</th><th>v</th><th>l</th><th>expected f cos</th><th>result</th><th>tolerance</th><th>material</th></tr>
{% for w in r.worst %}<tr><td><code>{{ w.id }}</code></td><td class="{{ w.verdict }}">{{ w.verdict }}</td>
<td>{{ "%.3g"|format(w.worst_ratio) }}</td><td>{{ vec(w.v) }}</td><td>{{ vec(w.l) }}</td><td>{{ vec(w.f_cos) }}</td>
<td>{% if w.result.f_cos is defined %}{{ vec(w.result.f_cos) }}{% else %}f cos not supplied{% endif %}{% if w.result.pdf is defined %}<br>pdf {{ "%.6g"|format(w.result.pdf) }} (expected {{ "%.6g"|format(w.pdf) }}){% endif %}</td>
<td>abs {{ "%.3g"|format(w.tolerance.abs) }}, rel {{ "%.3g"|format(w.tolerance.rel) }}</td>
<td><code>{{ w.material['values']|tojson }}</code>{% if w.options is defined %}<br>options <code>{{ w.options|tojson }}</code>{% endif %}</td></tr>
{% endfor %}</table>
</body></html>
"""


def vec(x):
    return "(" + ", ".join("%.6g" % c for c in x) + ")"


# A plot shows at most this many groups (those with the largest worst ratio, in the report's
# order), each labelled with at most LABEL_CHARS characters: a vector file may name thousands of
# groups or a group in 5000 characters, and the figure would exceed what the plotting library
# draws (the eighth fresh tester's pass: the whole report was lost).
MAX_GROUPS, LABEL_CHARS = 40, 40


def plotted_groups(groups):
    if len(groups) <= MAX_GROUPS:
        return groups
    worst = sorted(range(len(groups)), key=lambda i: -groups[i]["worst_ratio"])[:MAX_GROUPS]
    return [groups[i] for i in sorted(worst)]


def control_escaped(text):
    # Control characters (C0, DEL, C1) as \\xNN, as the command's own table prints them: in a plot
    # label no font has their glyphs (matplotlib's warning wrote them raw to the terminal; the tenth
    # fresh tester's pass), and in the page they are raw bytes (the eleventh's).
    return "".join(f"\\x{ord(c):02x}" if ord(c) < 0x20 or 0x7f <= ord(c) < 0xa0 else c for c in text)


def label(name):
    # "$" escaped: matplotlib reads $...$ as mathematics and raised on "$\\frac{$" (the ninth fresh
    # tester's pass: the report was lost).
    short = name if len(name) <= LABEL_CHARS else name[:LABEL_CHARS - 3] + "..."
    return control_escaped(short).replace("$", r"\$")


def distribution_plot(groups, values, path, xlabel, limit=None):
    shown = plotted_groups(groups)
    names = [g["name"] for g in shown]
    if len(shown) < len(groups):
        xlabel += f"\n({len(shown)} of the {len(groups)} groups: those with the largest error over tolerance)"
    fig, ax = plt.subplots(figsize=(10, 0.35 * len(names) + 1.5))
    for i, name in enumerate(names):
        x = np.array([v for v in values.get(name, []) if v is not None], dtype=float)
        x = np.clip(x, 1e-12, 1e12)
        ax.scatter(x, np.full(x.shape, i) + np.linspace(-0.25, 0.25, len(x)) if len(x) else x, s=6, alpha=0.6)
    if limit is not None:
        ax.axvline(limit, color="r", linewidth=1)
    if not any(v is not None for g in names for v in values.get(g, [])):
        # Results without any f cos (a pdf, emission or delta lobes alone): nothing to draw, and a
        # log axis of no data raises (the ninth fresh tester's pass: the report was lost).
        ax.text(0.5, 0.5, "no f cos supplied", transform=ax.transAxes, ha="center", va="center")
    else:
        ax.set_xscale("log")
    ax.set_yticks(range(len(names)))
    ax.set_yticklabels([label(n) for n in names])
    ax.set_xlabel(xlabel)
    ax.grid(True, axis="x", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main(folder):
    with open(os.path.join(folder, "report.json"), encoding="utf-8") as f:
        r = json.load(f)
    os.makedirs(os.path.join(folder, "plots"), exist_ok=True)
    ratios, errors = {}, {}
    for v in r["vectors"]:
        ratios.setdefault(v["group"], []).append(v["f_cos_ratio"])
        errors.setdefault(v["group"], []).append(v["f_cos_error"])
    distribution_plot(r["groups"], ratios, os.path.join(folder, "plots", "ratio_by_group.png"),
                      "error of f cos over its tolerance (≤ 1 passes; clipped to [1e-12, 1e12])", limit=1.0)
    distribution_plot(r["groups"], errors, os.path.join(folder, "plots", "relative_error_by_group.png"),
                      "relative error of f cos, max over channels (|result − expected| / max(|expected|, abs))")
    # Every string the page shows (group names, ids, paths from the user's files) without control
    # characters, then HTML-escaped.
    env = Environment(autoescape=select_autoescape(default=True),
                      finalize=lambda x: control_escaped(x) if isinstance(x, str) else x)
    html = env.from_string(PAGE).render(r=r, vec=vec)
    with open(os.path.join(folder, "index.html"), "w", encoding="utf-8") as f:
        f.write(html)
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
