#!/usr/bin/env bash
# Band-limited flooding across light radii and map sizes, and standard flooding against JFA with
# both banded (issue 13): per configuration the flood phase's min/median, the passes chosen
# (auto) and the band's share of the grid, band and full side by side in one run.
# Usage: bash bench/band_sweep.sh [FRAMES] [WARMUP]   (default 3 frames after 1 warm-up)
set -euo pipefail
frames=${1:-3}
warmup=${2:-1}
bench=${FLOODLIGHT_BENCH:-build/release/bench/floodlight_bench}
export MESA_SHADER_CACHE_DISABLE=true

# One floodlight_bench run, one line: the configuration, flood min/median, frame median, passes,
# active share.
run() {
  local label=$1
  shift
  local out
  out=$("$bench" --frames "$frames" --warmup "$warmup" "$@" 2>&1)
  local flood frame passes share
  flood=$(grep -E "^  flood " <<<"$out" | awk '{print $3 " / " $6}')
  frame=$(grep -E "^  frame " <<<"$out" | awk '{print $6}')
  passes=$(grep -E "^flood passes" <<<"$out" | cut -d: -f2 | tr -d ' ')
  share=$(grep -E "^active share" <<<"$out" | awk '{print $6}')
  printf '| %s | %s | %s | %s | %s |\n' "$label" "$flood" "$frame" "${passes:--}" "${share:--}"
}

echo "| configuration | flood min / median ms | frame median ms | passes | active share |"
echo "|---|---|---|---|---|"
# JFA-L floods the light's map: its cost should follow the penumbra area, not the map.
for radius in 0.3 1.5 3.0; do
  for size in 512 1024 2048; do
    for region in band full; do
      run "jfa-l r $radius map $size $region" --method jfa-l --light-radius "$radius" \
        --shadow-map-size "$size" --flood-region "$region"
    done
  done
done
# JFA-E floods the 512^2 eye image (the map only finds the hard shadow).
for radius in 0.3 1.5 3.0; do
  for region in band full; do
    run "jfa-e r $radius $region" --method jfa-e --light-radius "$radius" --flood-region "$region"
  done
done
# Standard flooding against JFA, both banded, at the passes auto chooses for JFA.
for m in jfa-l flood-l jfa-e flood-e; do
  run "$m r 1.5 band" --method "$m" --light-radius 1.5
done
