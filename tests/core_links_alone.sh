#!/usr/bin/env bash
# core_links_alone.sh EXE: EXE's shared-library dependencies (ldd: transitive) include none of the
# libraries dspbr::core must not pull in, and EXE runs (exit 0).
set -euo pipefail
exe=$1
deps=$(ldd "$exe")
if bad=$(grep -E -i 'lib(ceres|OpenImageIO|tbb|glog)[^ ]*\.so' <<<"$deps"); then
  echo "$exe links libraries dspbr::core must not need:"
  echo "$bad"
  exit 1
fi
echo "$exe: no Ceres, OpenImageIO, TBB or glog among:"
awk '{print "  " $1}' <<<"$deps"
"$exe"
