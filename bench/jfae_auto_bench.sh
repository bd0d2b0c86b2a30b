#!/usr/bin/env bash
# JFA-E's auto pass count, before and after (issue 30 item 2; docs/history/soft-shadows.md "JFA-E's
# auto pass count"): floodlight_bench --method jfa-e with --auto-passes geometric (the rule before)
# and measured (the default now), and a fixed count beside them, alternating within each round. Per
# round and configuration: the bench's median frame, flood, band and pass-count phase (ms) and the
# passes chosen; then per configuration the min and median of those medians.
# Usage: bash bench/jfae_auto_bench.sh [ROUNDS] [floodlight_bench options...]
#   e.g. bash bench/jfae_auto_bench.sh 3 --frames 5 --light-radius 1.5
# FLOODLIGHT_BENCH overrides the binary; JFAE_CONFIGS (;-separated) the configurations.
set -euo pipefail
rounds=${1:-3}
shift || true
bench=${FLOODLIGHT_BENCH:-build/release/bench/floodlight_bench}
export MESA_SHADER_CACHE_DISABLE=true
IFS=';' read -r -a configs <<<"${JFAE_CONFIGS:-jfa-e --auto-passes geometric;jfa-e;jfa-e --jfa-passes 6}"
# The median column of the bench's row named $2 (names may hold a space: "pass count").
median_of() { awk -v w="$2" 'index($0, "  " w " ") == 1 { sub(/.* median +/, ""); print $1 }' <<<"$1"; }
rows=$(mktemp); trap 'rm -f "$rows"' EXIT
for ((r = 1; r <= rounds; ++r)); do
  for c in "${configs[@]}"; do
    # shellcheck disable=SC2086
    out=$("$bench" --method $c "$@" 2>&1) || { echo "$out" >&2; exit 1; }
    frame=$(median_of "$out" frame) flood=$(median_of "$out" flood)
    band=$(median_of "$out" band) count=$(median_of "$out" "pass count")
    passes=$(grep -E "^flood passes" <<<"$out" | cut -d: -f2 | xargs || true)
    printf 'round %d | %-32s | frame %8s | flood %8s | band %6s | pass count %6s | passes %s\n' \
      "$r" "$c" "$frame" "$flood" "${band:--}" "${count:--}" "${passes:--}"
    printf '%s\t%s\t%s\t%s\t%s\n' "$c" "$frame" "$flood" "${band:-0}" "${count:-0}" >>"$rows"
  done
done
echo "min / median over rounds of the per-run medians, ms:"
stat() { # column $2 of configuration $1's rows: "min / median"
  awk -F'\t' -v c="$1" -v k="$2" '$1 == c { print $k }' "$rows" | sort -g |
    awk '{ v[n++] = $1 } END { printf "%.2f / %.2f", v[0], n % 2 ? v[int(n / 2)] : (v[n / 2 - 1] + v[n / 2]) / 2 }'
}
for c in "${configs[@]}"; do
  printf '  %-32s frame %s | flood %s | band %s | pass count %s\n' "$c" "$(stat "$c" 2)" \
    "$(stat "$c" 3)" "$(stat "$c" 4)" "$(stat "$c" 5)"
done
