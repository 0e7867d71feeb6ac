#!/usr/bin/env bash
# The whole test suite, as line 2 of the README's Quick start (and so CI) runs it, in three
# build directories:
#   build/       the project with its tests (Release): every CTest test;
#   build-asan/  the same tests built with AddressSanitizer + UndefinedBehaviorSanitizer
#                (-DPDR_SANITIZE=ON; any finding aborts the test): every test but the
#                oracle tests that need external meshers' long runs (label `slow`, none yet)
#                and the fuzz replays (the fuzz build below covers them);
#   build-fuzz/  clang with -DPDR_FUZZ=ON (every library instrumented, ASan + UBSan): each
#                libFuzzer target fuzzes PDR_FUZZ_SECONDS (15 by default) from its corpus.
# Idempotent: existing build directories are reused. Uses ccache when it is installed.
#   PDR_TEST_JOBS   parallel build/test jobs (default: the number of cores)
#   PDR_FUZZ_SECONDS   seconds per fuzz target (default 15)
#   PDR_SKIP_SANITIZE=1, PDR_SKIP_FUZZ=1   leave out a stage (for quick local runs)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${PDR_TEST_JOBS:-$(nproc)}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

stage() { echo "== run-tests: $*" >&2; }

stage "build/: the test suite"
cmake -S . -B build -G Ninja -DPDR_TESTS=ON "${launcher[@]}"
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure -j "$jobs"

if [ "${PDR_SKIP_SANITIZE:-0}" != 1 ]; then
  stage "build-asan/: the test suite under ASan + UBSan"
  cmake -S . -B build-asan -G Ninja -DPDR_TESTS=ON -DPDR_SANITIZE=ON "${launcher[@]}"
  cmake --build build-asan -j "$jobs"
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir build-asan --output-on-failure -j "$jobs" -LE 'fuzz|slow|proofs'
fi

if [ "${PDR_SKIP_FUZZ:-0}" != 1 ]; then
  stage "build-fuzz/: libFuzzer targets, ${PDR_FUZZ_SECONDS:-15} s each"
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DPDR_TESTS=ON -DPDR_FUZZ=ON \
    -DPDR_FUZZ_SECONDS="${PDR_FUZZ_SECONDS:-15}" "${launcher[@]}"
  cmake --build build-fuzz -j "$jobs" --target fuzz_targets
  ctest --test-dir build-fuzz --output-on-failure -j "$jobs" -L fuzz_run
fi
stage "all stages passed"
