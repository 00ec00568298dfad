#!/usr/bin/env bash
# The undefined-behaviour pass that CI runs after the README's test command (.ci/run;
# docs/limits.md, "Sanitizers"):
# builds the library, the dspbr tool and the GoogleTest suite into ${SANITIZE_DIR:-build-sanitize}
# with AddressSanitizer and UndefinedBehaviorSanitizer (any report fails the test that hit it)
# and with link-time optimisation under -Werror=odr (a one-definition-rule clash between
# translation units fails the link), then runs the GoogleTest cases (the tests that run the
# dspbr tool run the sanitized one). Installs packages first (scripts/setup.sh).
# -g1: line tables only, enough for the file:line of every frame in a report; full debug
# information (-g) made the compile 1.6x slower and the LTO links larger (tests/test_conformance.cpp:
# 16.5 s with -g, 10.4 s with -g1).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/setup.sh"
build="${SANITIZE_DIR:-$here/build-sanitize}"
flags="-O1 -g1 -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined"
lto="-flto=auto -Werror=odr"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=None \
  -DCMAKE_CXX_FLAGS="$flags $lto" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined $lto" \
  -DDSPBR_BUILD_BENCH=OFF -DDSPBR_BUILD_PYTHON=OFF -DDSPBR_FUZZ=OFF -DDSPBR_INSTALL=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target dspbr dspbr_tests
cd "$build"
# halt_on_error: the first report ends the process (the test fails); leaks are reports too.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:abort_on_error=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
# The GoogleTest cases (names Suite.Case); the shader, Python and example entries run in the
# main pass. Left out here, as the main pass runs them: the numerical sweeps that repeat code the
# other cases run under the sanitizers (the chi-square of the shader library's sampling, its delta
# lobes over the whole vector set, QMC against the quadrature, the quadrature at 1e-11, the white
# glass furnace), 7 of the pass's 17 minutes of test time.
heavy='^(ShaderLibrary\.SamplingMatchesPdfByChiSquare|ShaderLibrary\.EmissionAndDeltaLobesAsTheVectors'
heavy+='|LutQuadrature\.AgreesWithQmcOnEveryIntegrand|LutQuadrature\.StatedErrorBoundsTheTrueErrorOverTheDomain'
heavy+='|TransmissionCompensation\.WhiteGlassFurnaceWithinOnePercent)$'
ctest --output-on-failure -j "$(nproc)" -R '\.' -E "$heavy"
