#!/bin/bash
# One seeded mistake judged by the kit (tests/shader_seeded_mistakes.cmake): `dspbr conformance
# check` must fail its results (exit 1) and rank CAUSE first in report.json's diagnosis.
# usage: seeded_check.sh DSPBR VECTORS RESULTS_DIR NAME CAUSE
set -uo pipefail
dspbr=$1 vectors=$2 dir=$3 name=$4 cause=$5
"$dspbr" conformance check "$vectors" "$dir/$name.json" --no-html --out "$dir/report-$name"
rc=$?
if [ "$rc" -ne 1 ]; then
  echo "seeded mistake $name: conformance check exited $rc, expected 1 (the mistake fails)"
  exit 1
fi
/usr/bin/python3 - "$dir/report-$name/report.json" "$name" "$cause" <<'PY'
import json, sys
report, name, cause = json.load(open(sys.argv[1])), sys.argv[2], sys.argv[3]
d = report["diagnosis"]
ranked = [(c["cause"], c["explains"], c["contradicts"]) for c in d["causes"]]
print(f"{name}: {d['failing']} failing vectors; causes (explains, contradicts): {ranked}")
for g in report["groups"]:
    if "diagnosis" in g:
        top = g["diagnosis"]["causes"][:2]
        print(f"  {g['name']}: {g['diagnosis']['failing']} failing; {[(c['cause'], c['explains'], c['contradicts']) for c in top]}")
if not ranked or ranked[0][0] != cause:
    sys.exit(f"seeded mistake {name}: first-ranked cause {ranked[0][0] if ranked else None}, expected {cause}")
# The ranking has power: the cause explains nearly every failure and contradicts no passing vector.
if ranked[0][1] < 0.9 * d["failing"] or ranked[0][2] != 0:
    sys.exit(f"seeded mistake {name}: {cause} explains {ranked[0][1]} of {d['failing']} (needs 90 %), contradicted by {ranked[0][2]}")
PY
