#!/usr/bin/env bash
# Runs a libFuzzer target for SECONDS (default 60): bash scripts/fuzz.sh TARGET|all [SECONDS].
# Targets: plan, points, points3d, input_script, camera_path, gltf, capture_script, png_mask
# (fuzz/). It builds the clang preset `fuzz`, starts from the committed seeds (fuzz/corpus/TARGET,
# never modified) plus what earlier runs found (build/fuzz/corpus/TARGET), and stops at the first
# crash, leak or timeout, whose input is written to build/fuzz/artifacts/ (make it a regression
# fixture named after the bug).
# Targets run side by side, one per core (FLOODLIGHT_FUZZ_JOBS=N to change).
# Prints the executions per second and in total. FLOODLIGHT_FUZZ_SEED=N fixes libFuzzer's seed:
# from a clean build/fuzz the run is then the same sequence of inputs on every machine (CI uses 1;
# a longer run with that seed here covers what CI's shorter one tries).
set -euo pipefail
cd "$(dirname "$0")/.."
target=${1:?usage: bash scripts/fuzz.sh TARGET|all [SECONDS]}
seconds=${2:-60}
targets=(plan points points3d input_script camera_path gltf capture_script png_mask)
[ "$target" = all ] || targets=("$target")

cmake --preset fuzz >/dev/null
cmake --build build/fuzz -j "$(nproc)" --target "${targets[@]/#/fuzz_}"
mkdir -p build/fuzz/artifacts
seed=()
[ -n "${FLOODLIGHT_FUZZ_SEED:-}" ] && seed=(-seed="$FLOODLIGHT_FUZZ_SEED")

# One target for the whole time; its verdict goes to build/fuzz/TARGET.verdict.
fuzz_one() {
  local t=$1 found=build/fuzz/corpus/$1 log=build/fuzz/$1.log runs
  mkdir -p "$found"
  # -rss_limit_mb and -timeout turn unbounded memory and hangs into failures.
  if ! "build/fuzz/fuzz/fuzz_$t" "$found" "fuzz/corpus/$t" -max_total_time="$seconds" "${seed[@]}" \
      -rss_limit_mb=2048 -timeout=10 -artifact_prefix="build/fuzz/artifacts/$t-" \
      -print_final_stats=1 >"$log" 2>&1; then
    echo failed >"build/fuzz/$t.verdict"
    return 1
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
  echo "fuzz_$t: $runs executions in ${seconds} s ($((runs / seconds)) per second), no failure" \
    >"build/fuzz/$t.verdict"
}

# Each target is one single-threaded process: as many run at once as there are cores, each
# still for the whole time with the same seed (CI's 2 cores: 7 x 20 s in 80 s rather than 140).
jobs=${FLOODLIGHT_FUZZ_JOBS:-$(nproc)}
running=0
for t in "${targets[@]}"; do
  rm -f "build/fuzz/$t.verdict"
  if [ "$running" -ge "$jobs" ]; then
    wait -n || true
    running=$((running - 1))
  fi
  fuzz_one "$t" &
  running=$((running + 1))
done
wait || true
status=0
for t in "${targets[@]}"; do
  if [ "$(cat "build/fuzz/$t.verdict" 2>/dev/null)" = failed ] || [ ! -f "build/fuzz/$t.verdict" ]; then
    tail -40 "build/fuzz/$t.log"
    echo "fuzz_$t: FAILED (input under build/fuzz/artifacts/)" >&2
    status=1
  else
    cat "build/fuzz/$t.verdict"
  fi
done
exit "$status"
