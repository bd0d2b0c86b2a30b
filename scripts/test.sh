#!/usr/bin/env bash
# All tests: install what is needed, build release (warnings are errors) and run every test
# (CPU, headless EGL, window under Xvfb); each fuzz target for 20 s; then the same suite in the
# ASan+UBSan build.
# FLOODLIGHT_SKIP_ASAN=1 skips the sanitizer pass (for quick local runs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export MESA_SHADER_CACHE_DISABLE=true
jobs=$(nproc)

cmake --preset release >/dev/null
cmake --build --preset release -j "$jobs"
ctest --preset release -j "$jobs"

# Every libFuzzer target (fuzz/) for a short fixed time from its committed seeds, with a fixed
# libFuzzer seed (the same inputs each time); a crash, leak, hang or unbounded allocation fails
# the run (bash scripts/fuzz.sh TARGET SECONDS runs longer, with a random seed).
FLOODLIGHT_FUZZ_SEED=1 bash scripts/fuzz.sh all "${FLOODLIGHT_FUZZ_SECONDS:-20}"

if [ "${FLOODLIGHT_SKIP_ASAN:-0}" != 1 ]; then
  cmake --preset asan >/dev/null
  cmake --build --preset asan -j "$jobs"
  ctest --preset asan -j "$jobs"
fi
