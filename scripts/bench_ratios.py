#!/usr/bin/python3
"""The reference BSDF's (or with --shader the shader library's) speed as ratios to the bare GGX eval.

docs/bsdf.md, "Speed"; with --shader, docs/renderer.md, "Cost" (the C++ compile of shaders/dspbr.h,
BM_Shader/*, against a bare float GGX eval in the same run).

Runs build/dspbr_bench on the BSDF benchmarks and the table lookups with random interleaving
(every repetition of every benchmark in a shuffled order, so that a slow spell of the machine
spreads over all of them) and prints a Markdown table: the median CPU time over the repetitions,
its ratio to the median of BM_Eval/bare_ggx, the spread of the ratio (each repetition of a
benchmark against the bare median), the target and whether the median holds it; with --shader also
prepare / eval of each material against its target (prepare alone at most 3 evals).

    /usr/bin/python3 scripts/bench_ratios.py [--bench build/dspbr_bench] [--repetitions 10] [--shader]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

# Targets: ratio to bare_ggx for the BSDF benchmarks, nanoseconds per lookup for the table lookups
# (the warp benchmarks time a part of one, without a target).
RATIO_TARGETS = {
    "BM_Eval/plastic": 5, "BM_Eval/metal": 3, "BM_Eval/thin_film": 10, "BM_Eval/carpaint": 10,
    "BM_Eval/full": 50, "BM_Sample/full": 100,
}
LOOKUP_TARGET_NS = 10
LOOKUPS = {"BM_FitLutTableLookup/0": "published", "BM_FitLutTableLookup/1": "renderer",
           "BM_SliceLookup/0": "lobe's slice, published", "BM_SliceLookup/1": "lobe's slice, renderer",
           "BM_SliceLookupPair": "lobe's slice, renderer, two cosines at a time",
           "BM_WarpGgxCos": "the renderer layout's cos warp alone, one cosine",
           "BM_WarpGgxCosPair": "the renderer layout's cos warp alone, two cosines at a time",
           "BM_LookupGeneratedC": "generated C", "BM_FitLutBilinearFloat": "float bilinear, published 32x32"}
LOOKUPS_PER_ITERATION = 1024  # bench/bench_fits.cpp: 1024 (mu, r) per iteration
FILTER = "BM_(Eval|Sample)/[a-z_]*$|BM_FitLutTableLookup|BM_SliceLookup|BM_WarpGgxCos|BM_LookupGeneratedC|BM_FitLutBilinearFloat"
# --shader: the shader library per hit (prepare + eval as a textured material pays it).
SHADER_TARGETS = {"BM_Shader/prepare_eval/plastic": 6, "BM_Shader/prepare_eval/metal": 5,
                  "BM_Shader/prepare_eval/carpaint": 12, "BM_Shader/prepare_eval/full": 20}
SHADER_FILTER = "BM_Shader/"
# --shader: prepare alone costs at most this many evals of the same material.
PREPARE_PER_EVAL_TARGET = 3


def fmt_ns(ns):
    return f"{ns / 1000:.2f} µs" if ns >= 1000 else f"{ns:.1f} ns"


def main():
    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bench", default=os.path.join(here, "build", "dspbr_bench"), help="dspbr_bench binary")
    ap.add_argument("--repetitions", type=int, default=10, help="repetitions per benchmark (default 10)")
    ap.add_argument("--shader", action="store_true", help="the shader library's C++ compile (BM_Shader/*)")
    args = ap.parse_args()
    bare_name = "BM_Shader/bare_ggx" if args.shader else "BM_Eval/bare_ggx"
    targets = SHADER_TARGETS if args.shader else RATIO_TARGETS
    if not os.access(args.bench, os.X_OK):
        print(f"bench_ratios: {args.bench}: not an executable (build it: cmake --build build --target dspbr_bench)",
              file=sys.stderr)
        return 2
    if args.repetitions < 1:
        print("bench_ratios: --repetitions must be >= 1", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "bench.json")
        run = subprocess.run([args.bench, f"--benchmark_filter={SHADER_FILTER if args.shader else FILTER}", f"--benchmark_repetitions={args.repetitions}",
                        "--benchmark_enable_random_interleaving=true", f"--benchmark_out={out}",
                        "--benchmark_out_format=json"], stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, text=True)
        if run.returncode != 0:
            last = (run.stderr.strip().splitlines() or ["no message"])[-1]
            print(f"bench_ratios: {args.bench} failed (exit {run.returncode}): {last}", file=sys.stderr)
            return 2
        with open(out) as f:
            data = json.load(f)
    runs = {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "iteration":
            runs.setdefault(b["run_name"], []).append(b["cpu_time"])  # ns (the benchmarks' default unit)
    bare = statistics.median(runs[bare_name])
    print(f"bare GGX eval: median {fmt_ns(bare)} over {len(runs[bare_name])} repetitions\n")
    print("| benchmark | median CPU time | ratio to bare_ggx | ratio range | target | held |")
    print("|---|---:|---:|---:|---:|:---:|")
    # bare_ggx, then the evals, then the samples, each in name order
    order = sorted((n for n in runs if n not in LOOKUPS),
                   key=lambda n: (n != bare_name, not n.startswith("BM_Eval/"), n))
    for name in order:
        times = runs[name]
        med = statistics.median(times)
        target = targets.get(name)
        held = "" if target is None else ("yes" if med / bare <= target else "no")
        print(f"| `{name}` | {fmt_ns(med)} | {med / bare:.2f} | {min(times) / bare:.2f}–{max(times) / bare:.2f} | "
              f"{'≤ ' + str(target) if target else ''} | {held} |")
    for name, label in LOOKUPS.items():
        if name not in runs:
            continue
        per = [t / LOOKUPS_PER_ITERATION for t in runs[name]]
        med = statistics.median(per)
        verdict = "| |" if name.startswith("BM_Warp") else \
            f"≤ {LOOKUP_TARGET_NS} ns | {'yes' if med <= LOOKUP_TARGET_NS else 'no'} |"
        print(f"| `{name}` ({label}, per item) | {fmt_ns(med)} | | {min(per):.1f}–{max(per):.1f} ns | {verdict}")
    if args.shader:
        # prepare / eval of each material, medians of the same run
        print("\n| material | prepare / eval | target | held |")
        print("|---|---:|---:|:---:|")
        for name in sorted(n for n in runs if n.startswith("BM_Shader/prepare/")):
            material = name[len("BM_Shader/prepare/"):]
            evals = runs.get("BM_Shader/eval/" + material)
            if not evals:
                continue
            q = statistics.median(runs[name]) / statistics.median(evals)
            held = "yes" if q <= PREPARE_PER_EVAL_TARGET else "no"
            print(f"| {material} | {q:.2f} | ≤ {PREPARE_PER_EVAL_TARGET} | {held} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
