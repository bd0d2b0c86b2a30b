#!/usr/bin/env bash
# Foundation numbers (docs/history/hard-shadows-and-frame-costs.md): frame time of the default
# scene at 512² with a 1024² shadow map, and the depth (shadow-map) pass of the 216,440-triangle
# scene, with peak RSS.
# Each configuration runs RUNS times as separate processes (default 3), 30 frames after 5 warm-up.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-3}
build=build/release
bench=$build/bench/floodlight_bench
export MESA_SHADER_CACHE_DISABLE=true
[ -x "$bench" ] || { echo "build first: cmake --preset release && cmake --build --preset release" >&2; exit 1; }
"$build/app/floodlight" make-scene --size fantasy2 --out "$build/fantasy2.glb" >/dev/null

for scene in assets/default.glb "$build/fantasy2.glb"; do
  for i in $(seq "$runs"); do
    echo "== $scene, run $i"
    "$bench" --scene "$scene" --width 512 --height 512 --shadow-map-size 1024 --frames 30 --warmup 5
  done
done
