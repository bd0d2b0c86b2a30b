#!/usr/bin/env bash
# Band-limited against full-grid flooding, side by side in one run (issue 13): each method's frame
# and flood medians, passes chosen and active share, alternating configurations per round.
# Usage: bash bench/band_bench.sh [ROUNDS] [floodlight_bench options...]
set -euo pipefail
rounds=${1:-2}
shift || true
bench=${FLOODLIGHT_BENCH:-build/release/bench/floodlight_bench}
export MESA_SHADER_CACHE_DISABLE=true
configs=("pcss --pcss-preset 16/16" "jfa-l" "jfa-l --flood-region full" "jfa-e" "jfa-e --flood-region full"
         "jfa-e --jfa-passes 6" "jfa-e --jfa-passes 6 --flood-region full")
for ((r = 1; r <= rounds; ++r)); do
  for c in "${configs[@]}"; do
    # shellcheck disable=SC2086
    out=$("$bench" --method $c "$@" 2>&1)
    frame=$(grep -E "^  frame " <<<"$out" | awk '{print $3, $6}')
    flood=$(grep -E "^  flood " <<<"$out" | awk '{print $3, $6}' || true)
    band=$(grep -E "^  band " <<<"$out" | awk '{print $3, $6}' || true)
    passes=$(grep -E "^flood passes" <<<"$out" | cut -d: -f2 || true)
    share=$(grep -E "^active share" <<<"$out" | awk '{print $6}' || true)
    printf 'round %d | %-40s | frame min/med %s ms | band %s | flood %s | passes%s | share %s\n' \
      "$r" "$c" "$frame" "${band:--}" "${flood:--}" "${passes:- -}" "${share:--}"
  done
done
