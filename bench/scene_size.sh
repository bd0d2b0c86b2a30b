#!/usr/bin/env bash
# Does the flooding time depend on the scene or on the resolution? (thesis §5.5, Fig. 5.10)
# JFA-L on the five thesis scene sizes (634 ... 216,440 triangles) at shadow-map sizes 256², 512²
# and 1024² with a 512² screen; JFA-E on the same scenes at screen sizes 256², 512² and 1024²
# with a 1024² map. Every configuration is one process: FRAMES timed frames after 2 warm-up
# frames; floodlight_bench prints min and median per pass ("flood" is the jump flooding).
# Usage: bash bench/scene_size.sh [FRAMES]   (default 5; light radius 1.5, 6 passes)
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-5}
build=build/release
bench=$build/bench/floodlight_bench
export MESA_SHADER_CACHE_DISABLE=true
[ -x "$bench" ] || { echo "build first: cmake --preset release && cmake --build --preset release" >&2; exit 1; }

sizes=(knight teapot bunny fantasy fantasy2)
for s in "${sizes[@]}"; do
  [ -f "$build/$s.glb" ] || "$build/app/floodlight" make-scene --size "$s" --out "$build/$s.glb" >/dev/null
done

run() { # label, then floodlight_bench arguments
  local label=$1; shift
  local out
  out=$("$bench" --frames "$frames" --warmup 2 --light-radius 1.5 --jfa-passes 6 "$@")
  local tris flood frame
  tris=$(sed -n 's/^scene: .*, \([0-9]*\) triangles$/\1/p' <<<"$out")
  flood=$(awk '$1 == "flood" && $2 == "min" {print $3 " / " $6}' <<<"$out")
  frame=$(awk '$1 == "frame" && $2 == "min" {print $3 " / " $6}' <<<"$out")
  printf '%-8s %-9s %9s  flood %-21s frame %s ms\n' "$label" "$s" "$tris" "$flood" "$frame"
}

echo "JFA-L: screen 512², shadow map 256² / 512² / 1024² (min / median ms)"
for map in 256 512 1024; do
  for s in "${sizes[@]}"; do
    run "map $map" --scene "$build/$s.glb" --method jfa-l --width 512 --height 512 --shadow-map-size "$map"
  done
done
echo "JFA-E: shadow map 1024², screen 256² / 512² / 1024² (min / median ms)"
for screen in 256 512 1024; do
  for s in "${sizes[@]}"; do
    run "scr $screen" --scene "$build/$s.glb" --method jfa-e --width "$screen" --height "$screen" --shadow-map-size 1024
  done
done
