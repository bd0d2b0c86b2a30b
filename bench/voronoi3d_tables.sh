#!/usr/bin/env bash
# The thesis' 3D Voronoi experiments (§4.6, Fig. 4.16 and 4.17) with `floodlight voronoi3d`:
#   errors  - error voxels of every variant (3D JFA, JFA+1, JFA+2, JFA^2; slice JFA, slice 1+JFA)
#             for several sizes, site counts and seeds (CPU; GL gives the same grids, see times);
#   times   - every variant on CPU and GL side by side in one run (--backend both: each flood
#             --runs times, min and median; GL's passes after a warm-up run, upload and
#             read-back apart), with GL == CPU checked voxel for voxel.
#   shaders - the GL pass with the shaders of folder DIR (--shader-dir) against the embedded ones,
#             alternating ROUNDS times, each --runs 3 (min and median of the passes), and the two
#             EXRs compared byte for byte (an optimisation must not change the result).
# Prints one table row per line (Markdown). Usage:
#   bash bench/voronoi3d_tables.sh errors "64 128" "100 1000 10000" "1 2 3"
#   bash bench/voronoi3d_tables.sh times "64 128" 1000 RUNS
#   bash bench/voronoi3d_tables.sh shaders 64 1000 DIR ROUNDS
set -euo pipefail
part=${1:?errors or times}
sizes=${2:-"64 128"}
counts=${3:-"100 1000 10000"}
bin=${FLOODLIGHT:-build/release/app/floodlight}
export MESA_SHADER_CACHE_DISABLE=true

# Error lines: "  LABEL on SxSxS, N sites: E error voxels of V (P%)" -> "LABEL|E|P".
errors() { sed -nE 's/^  (GL |CPU )?(.+) on [0-9x]+, [0-9]+ sites?: ([0-9]+) error voxels? of [0-9]+ \(([0-9.]+%)\).*/\2|\3|\4/p'; }

if [[ $part == errors ]]; then
  seeds=${4:-"1 2 3"}
  echo "| grid | sites | variant | error voxels per seed ($seeds) | mean | mean % of voxels |"
  echo "|---|---|---|---|---|---|"
  for s in $sizes; do
    for n in $counts; do
      declare -A per=() pct=()
      labels=()
      for seed in $seeds; do
        while IFS='|' read -r label e p; do
          [[ -z ${per[$label]+x} ]] && labels+=("$label")
          per[$label]="${per[$label]:-} $e"
          pct[$label]="${pct[$label]:-} ${p%\%}"
        done < <("$bin" voronoi3d --size "$s" --sites "$n" --seed "$seed" --compare --backend cpu | errors)
      done
      for label in "${labels[@]}"; do
        mean=$(awk '{s=0; for(i=1;i<=NF;++i) s+=$i; printf "%.1f", s/NF}' <<<"${per[$label]}")
        meanp=$(awk '{s=0; for(i=1;i<=NF;++i) s+=$i; printf "%.4f%%", s/NF}' <<<"${pct[$label]}")
        echo "| ${s}^3 | $n | $label |${per[$label]} | $mean | $meanp |"
      done
      unset per pct
    done
  done
elif [[ $part == times ]]; then
  runs=${4:-5}
  echo "| grid | sites | variant | CPU min / median ms | GL min / median ms (passes) | GL upload + read-back ms | GL == CPU | error voxels |"
  echo "|---|---|---|---|---|---|---|---|"
  for s in $sizes; do
    for n in $counts; do
      "$bin" voronoi3d --size "$s" --sites "$n" --compare --backend both --runs "$runs" | awk -v s="$s" -v n="$n" '
        /^[^ ].*: steps/ { label = substr($0, 1, index($0, ": steps") - 1) }
        /^  CPU: min/ { cpu = $3 " / " $9 }
        /^  GL: min/ { gl = $3 " / " $9; up = $13; rd = $20 }
        /^  GL == CPU:/ { same = ($4 == "identical,") ? "identical" : "DIFFER" }
        / error voxels? of / && /^  [^ ]/ && !/^  (CPU|GL): / {
          sub(/^  /, ""); split($0, a, ": "); split(a[2], b, " ");
          printf "| %s^3 | %s | %s | %s | %s | %s + %s | %s | %s |\n", s, n, label, cpu, gl, up, rd, same, b[1] }'
    done
  done
elif [[ $part == shaders ]]; then
  dir=${4:?shader folder}
  rounds=${5:-3}
  out=$(mktemp -d)
  echo "| round | variant | grid | sites | shaders | GL passes min / median ms | EXR equal |"
  echo "|---|---|---|---|---|---|---|"
  for ((r = 1; r <= rounds; ++r)); do
    for v in jfa slices; do
      for which in before after; do
        opt=()
        [[ $which == before ]] && opt=(--shader-dir "$dir")
        t=$("$bin" voronoi3d --size "$sizes" --sites "$counts" --variant "$v" --backend gl --runs 3 \
              "${opt[@]}" --out "$out" --name "$which" | awk '/^  GL: min/ { print $3 " / " $9 }')
        same=-
        [[ $which == after ]] && { cmp -s "$out/before.exr" "$out/after.exr" && same=yes || same=NO; }
        echo "| $r | $v | ${sizes}^3 | $counts | $which | $t | $same |"
      done
    done
  done
  rm -rf "$out"
else
  echo "unknown part $part (errors, times or shaders)" >&2
  exit 2
fi
