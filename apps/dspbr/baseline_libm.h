// The same fit on every x86-64 machine. glibc picks libm's exp, log, pow, sin, atan, ... among
// builds for SSE2, AVX, FMA and FMA4 by the CPU it runs on (IFUNC); they differ in the last bit,
// and the fits amplify that (between two of them the sheen Lambda fit's coefficients moved in the
// 2nd digit and its maximum error from 0.9 % to 2.6 %: docs/design/fits.md). `dspbr fit`
// therefore runs with those CPU features masked by GLIBC_TUNABLES, i.e. on the SSE2 builds that
// every x86-64 CPU runs. glibc reads the variable only when a process starts: the front sets it
// for dspbr-full, and dspbr-full started without it re-executes itself once.
#pragma once

namespace dspbr::cli {

// The GLIBC_TUNABLES entry that masks the features: "glibc.cpu.hwcaps=-AVX,-AVX2,-FMA,-FMA4".
extern const char* const kBaselineLibmTunable;

// True when argv names a command that runs on the baseline libm (`fit`), on x86-64 glibc.
bool wants_baseline_libm(int argc, char** argv);

// Appends kBaselineLibmTunable to GLIBC_TUNABLES (after the user's own entries, so it wins over a
// glibc.cpu.hwcaps of theirs) unless the variable already ends with it; true when it changed the
// environment (the running process does not see the change: only the programs it executes).
bool set_baseline_libm_environment();

// In dspbr-full: for a command that wants the baseline libm, started without it, replaces the
// process by itself with the environment set (same arguments). Returns when nothing is to be done,
// or when the re-execution failed (a warning on stderr; the run goes on with this CPU's libm).
void run_on_baseline_libm(int argc, char** argv);

}  // namespace dspbr::cli
