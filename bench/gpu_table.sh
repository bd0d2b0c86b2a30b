#!/usr/bin/env bash
# The frame-cost table (issue 28; docs/history/gpu-and-lean-frame.md "GPU frame costs"): for every
# method x scene x resolution, the median whole frame and the median flood, in ms, and the MB of
# render targets the frame writes (from the formats: floodlight_bench's "written"), from
# floodlight_bench on whatever GPU the EGL context gets. The first line names the GL renderer.
# Numbers from two runs differ with the machine's clocks and load: compare methods within one table,
# not tables across runs.
#
# From a checkout with a release build (cmake --preset release && cmake --build --preset release):
#   bash bench/gpu_table.sh [OPTIONS]
# On a machine with a GPU but without our packages, from a bundle made by
# ../shared/tools/gpu-bundle.sh and unpacked to /opt/fl (its README):
#   bash bench/gpu_table.sh --run /opt/fl/payload/run [OPTIONS]
# Options:
#   --run PATH       run the binaries as `PATH floodlight_bench ...` (a bundle's run script)
#   --sizes LIST     WxH:MAP,... (default 512x512:1024,1920x1080:2048,3840x2160:4096; on llvmpipe
#                    256x256:512,512x512:1024, since a 1080p frame takes seconds there)
#   --scenes LIST    default,fantasy2 (fantasy2: 216,440 triangles, made with make-scene)
#   --frames N       timed frames a cell, after 3 warm-up (default 20; 5 on llvmpipe)
#   --methods LIST   ;-separated floodlight_bench method arguments (default: the table below)
#   --raw FILE       also write one line a cell: scene|size|method|frame min med|flood min med
#   --timeout S      seconds a cell may take before it reads "timeout" (default 300)
# FLOODLIGHT_EGL_DEVICE=N chooses the EGL device (floodlight --help); unset, the first that works.
set -euo pipefail
cd "$(dirname "$0")/.."

run="" sizes="" scenes="default,fantasy2" frames="" raw="" timeout_s=300
methods="hard;pcf;pcss --pcss-preset 16/16;pcss --pcss-preset 32/64;vsm;jfa-l;jfa-l --flood-region band;jfa-l --flood-region full;jfa-e;jfa-e --jfa-passes 6;jfa-e --flood-region full;flood-l;flood-e"
while [ $# -gt 0 ]; do
  case "$1" in
    --run) run=$2; shift 2 ;;
    --sizes) sizes=$2; shift 2 ;;
    --scenes) scenes=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --methods) methods=$2; shift 2 ;;
    --raw) raw=$2; shift 2 ;;
    --timeout) timeout_s=$2; shift 2 ;;
    -h|--help) sed -n '2,22p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "gpu_table.sh: unknown option $1 (--help lists them)" >&2; exit 2 ;;
  esac
done

# Our binaries, from the bundle or from this checkout's release build.
if [ -n "$run" ]; then
  bench=("$run" floodlight_bench); floodlight=("$run" floodlight)
else
  bench=(build/release/bench/floodlight_bench); floodlight=(build/release/app/floodlight)
  for b in "${bench[0]}" "${floodlight[0]}"; do
    [ -x "$b" ] || { echo "gpu_table.sh: $b missing (build the release preset, or --run a bundle)" >&2; exit 2; }
  done
fi

export MESA_SHADER_CACHE_DISABLE=${MESA_SHADER_CACHE_DISABLE:-true}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT

# The renderer, from a one-frame run: it also picks the sizes that fit the machine.
probe=$("${bench[@]}" --width 64 --height 64 --shadow-map-size 256 --frames 1 --warmup 0 2>&1) || {
  echo "$probe" >&2; exit 1; }
context=$(grep -m1 '^context:' <<<"$probe" | sed 's/^context: //')
soft=0; grep -qiE 'llvmpipe|softpipe' <<<"$context" && soft=1
[ -n "$sizes" ] || { [ $soft = 1 ] && sizes="256x256:512,512x512:1024" || sizes="512x512:1024,1920x1080:2048,3840x2160:4096"; }
[ -n "$frames" ] || { [ $soft = 1 ] && frames=5 || frames=20; }

echo "renderer: $context"
echo "floodlight_bench, $frames frames after 3 warm-up; cells: median frame ms (median flood ms), MB of targets the frame writes; $(date -u +%Y-%m-%dT%H:%MZ)"

scene_args() {
  case "$1" in
    default) ;;
    fantasy2)
      [ -f "$work/fantasy2.glb" ] || "${floodlight[@]}" make-scene --size fantasy2 --out "$work/fantasy2.glb" >/dev/null
      echo "--scene $work/fantasy2.glb" ;;
    *) echo "--scene $1" ;;
  esac
}

# value_of OUTPUT ROW WORD: on the bench's timing row ROW ("frame", "flood", ...), the value after
# WORD ("min", "median", "written"); "-" when the row or the word is missing.
value_of() {
  awk -v n="$2" -v w="$3" '{ line = $0; sub(/^ +/, "", line)
                   if (index(line, n " ") == 1 && $0 ~ / min +[0-9.]+ ms +median/) {
                     for (i = 1; i <= NF; ++i) if ($i == w) { print $(i + 1); exit } } }' <<<"$1" |
    grep . || echo "-"
}

IFS=',' read -ra size_list <<<"$sizes"
IFS=',' read -ra scene_list <<<"$scenes"
IFS=';' read -ra method_list <<<"$methods"
[ -z "$raw" ] || : >"$raw"
for scene in "${scene_list[@]}"; do
  extra=$(scene_args "$scene")
  echo
  echo "scene: $scene"
  header="| method |"; rule="|---|"
  for s in "${size_list[@]}"; do header+=" ${s%%:*}, map ${s##*:} |"; rule+="---|"; done
  echo "$header"; echo "$rule"
  for m in "${method_list[@]}"; do
    line="| $m |"
    for s in "${size_list[@]}"; do
      wh=${s%%:*}; map=${s##*:}
      # shellcheck disable=SC2086 # the method's and the scene's arguments are word lists
      if out=$(timeout "$timeout_s" "${bench[@]}" --method $m $extra --width "${wh%x*}" \
          --height "${wh#*x}" --shadow-map-size "$map" --frames "$frames" --warmup 3 2>&1); then
        fm=$(value_of "$out" frame median); fl=$(value_of "$out" flood median)
        line+=" $fm ($fl), $(value_of "$out" frame written) MB |"
        [ -z "$raw" ] || echo "$scene | $wh map $map | $m | frame $(value_of "$out" frame min) $fm | flood $(value_of "$out" flood min) $fl" >>"$raw"
      else
        rc=$?; [ $rc = 124 ] && line+=" timeout |" || line+=" error |"
        echo "gpu_table.sh: $scene $s $m failed (exit $rc): $(tail -1 <<<"$out")" >&2
      fi
    done
    echo "$line"
  done
done
