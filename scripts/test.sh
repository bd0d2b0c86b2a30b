#!/usr/bin/env bash
# All tests: install what is needed, build release (warnings are errors) and run every test
# (CPU, headless EGL, window under Xvfb); then the same suite in the ASan+UBSan build.
# FLOODLIGHT_SKIP_ASAN=1 skips the sanitizer pass (for quick local runs).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export MESA_SHADER_CACHE_DISABLE=true
jobs=$(nproc)

cmake --preset release >/dev/null
cmake --build --preset release -j "$jobs"
ctest --preset release -j "$jobs"

if [ "${FLOODLIGHT_SKIP_ASAN:-0}" != 1 ]; then
  cmake --preset asan >/dev/null
  cmake --build --preset asan -j "$jobs"
  ctest --preset asan -j "$jobs"
fi
