#!/usr/bin/env bash
# The main job: install what is needed, build (release) and run floodlight on the built-in default
# scene — a window when a display is available, otherwise a headless render into captures/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release
exec ./build/release/app/floodlight "$@"
