#!/usr/bin/env bash
# The demonstrations of docs/conformance.md: the conformance vectors (seed 1, with the validation
# scenes) judged for three implementations that differ from the reference — the reference BSDF
# reading the published tables, the LUT-free fits (fits/dspbr_fits.hpp), and no energy
# compensation (src/dspbr/conformance/demo_tables.h) — then the summary of their reports written
# between the markers of docs/conformance.md.
#   bash scripts/conformance_demo.sh [OUT]     (OUT default: build/conformance-demo; ~20 s)
# Uses ${DSPBR_EXE:-build/dspbr} and /usr/bin/python3 (numpy, matplotlib, jinja2 for the HTML).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
exe="${DSPBR_EXE:-$here/build/dspbr}"
out="${1:-$here/build/conformance-demo}"
doc="${DSPBR_CONFORMANCE_DOC:-$here/docs/conformance.md}"
cd "$here"  # the vectors record the scene folder as given: data/dspbr/scenes/sphere
"$exe" conformance generate --out "$out/vectors" --scenes data/dspbr/scenes/sphere
for impl in published fits uncompensated; do
  "$exe" conformance reference "$out/vectors/vectors.json" --tables "$impl" --out "$out/results-$impl.json"
  status=0
  "$exe" conformance check "$out/vectors/vectors.json" "$out/results-$impl.json" --out "$out/report-$impl" \
    > "$out/check-$impl.txt" || status=$?
  if [ "$status" -gt 1 ]; then cat "$out/check-$impl.txt"; exit "$status"; fi
done
/usr/bin/python3 "$here/scripts/report/conformance_demo_summary.py" "$out" "$doc"
echo "reports in $out/report-{published,fits,uncompensated}/index.html; summary written to $doc"
