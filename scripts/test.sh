#!/usr/bin/env bash
# All tests: install what is needed, build and test the CPU libraries without GL, build release
# (warnings are errors) and run every test (CPU, headless EGL, window under Xvfb); each fuzz
# target for 20 s; then the same suite in the ASan+UBSan build. Ends with a timing report (each
# phase, the slowest tests), also written to build/test-timing.txt, and a warning when the whole
# run passes CI's budget of 40 minutes.
# FLOODLIGHT_SKIP_ASAN=1 skips the sanitizer pass (for quick local runs).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/test-timing.sh

phase setup bash scripts/setup.sh
export MESA_SHADER_CACHE_DISABLE=true
# The test presets (CMakePresets.json) also set GALLIVM_PERF=nopt: llvmpipe compiles shaders
# without LLVM's optimisation passes. Compiling is most of a GL test's time on llvmpipe and the
# tests draw at most 256^2, so the suite runs about a third faster; the pictures are the same
# (every golden and comparison passes both ways), and it is one more conforming driver
# configuration the tests hold on. Benchmarks and users' runs keep the optimised shaders.
jobs=$(nproc)

# The CPU libraries alone (issue 43): configured without GL (-DFLOODLIGHT_GL=OFF, preset cpu),
# with the GL, EGL, GLFW and epoxy headers shadowed by ones that stop the compile (cmake/no_gl/),
# built and tested. The preset disables the GL packages' lookups, so CMake warns that those two
# variables went unused: that is the point. ctest no_gl_configure checks the cache for lookups.
phase "cpu build + tests" eval 'cmake --preset cpu >/dev/null && cmake --build --preset cpu -j "$jobs" && ctest --preset cpu -j "$jobs"'

phase "release build" eval 'cmake --preset release >/dev/null && cmake --build --preset release -j "$jobs"'
phase "release tests" suite release ctest --preset release -j "$jobs"

# Every libFuzzer target (fuzz/) for a short fixed time from its committed seeds, with a fixed
# libFuzzer seed (the same inputs each time); a crash, leak, hang or unbounded allocation fails
# the run (bash scripts/fuzz.sh TARGET SECONDS runs longer, with a random seed).
phase "fuzz build + run" env FLOODLIGHT_FUZZ_SEED=1 bash scripts/fuzz.sh all "${FLOODLIGHT_FUZZ_SECONDS:-20}"

if [ "${FLOODLIGHT_SKIP_ASAN:-0}" != 1 ]; then
  phase "asan build" eval 'cmake --preset asan >/dev/null && cmake --build --preset asan -j "$jobs"'
  phase "asan tests" suite asan ctest --preset asan -j "$jobs"
fi
