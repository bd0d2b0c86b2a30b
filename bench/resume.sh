#!/usr/bin/env bash
# What `capture --resume` saves on a killed run (issue 16): one capture run without a break, one
# killed (SIGKILL) once KILL_AT of its FRAMES frames are finished, then that one resumed. The
# saving is the unbroken run's time minus the resumed run's; at most the frame in flight at the
# kill is rendered twice. Also prints what keeping the progress costs per frame.
# Usage: bench/resume.sh [FRAMES] [KILL_AT] [SIZE]   (defaults 20, 10, 128; build/release built)
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-20}
kill_at=${2:-10}
size=${3:-128}
bin=build/release/app/floodlight
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export MESA_SHADER_CACHE_DISABLE=true
cat >"$work/script.json" <<JSON
{"scene": "default", "camera": {"frames": $frames, "path": "default"}, "light": {"radius": 1.5},
 "resolutions": [[$size, $size]], "shadowMap": {"provider": "uniform", "size": 1024},
 "reference": {"samples": 64, "mapSize": 1024},
 "methods": ["hard", "pcf:3", "pcss:16/24", "jfa-l", "flood-l", "jfa-e", "flood-e"]}
JSON
now() { date +%s.%N; }

t0=$(now)
"$bin" capture "$work/script.json" --out "$work/unbroken" >"$work/unbroken.txt"
t1=$(now)
"$bin" capture "$work/script.json" --out "$work/killed" >/dev/null 2>&1 &
pid=$!
while kill -0 $pid 2>/dev/null &&
    [ $(($(wc -l 2>/dev/null <"$work/killed/progress.jsonl" || echo 0) - 1)) -lt "$kill_at" ]; do
    sleep 0.05
done
kill -9 $pid
wait $pid 2>/dev/null || true
t2=$(now)
done_before=$(($(wc -l <"$work/killed/progress.jsonl") - 1))
"$bin" capture "$work/script.json" --out "$work/killed" --resume >"$work/resumed.txt"
t3=$(now)
cut -d, -f1-16 "$work/unbroken/frames.csv" >"$work/a.csv"
cut -d, -f1-16 "$work/killed/frames.csv" >"$work/b.csv"
cmp -s "$work/a.csv" "$work/b.csv" && same="identical" || same="DIFFERENT"
python3 - "$t0" "$t1" "$t2" "$t3" "$frames" "$done_before" "$same" <<'PY'
import sys
t0, t1, t2, t3 = map(float, sys.argv[1:5]); frames, done, same = int(sys.argv[5]), int(sys.argv[6]), sys.argv[7]
full, killed, resumed = t1 - t0, t2 - t1, t3 - t2
print(f"unbroken run: {full:.1f} s for {frames} frames")
print(f"killed after {done} finished frames: {killed:.1f} s")
print(f"resumed: {resumed:.1f} s for the other {frames - done} frames")
print(f"--resume saves {full - resumed:.1f} s of {full:.1f} s ({100 * (full - resumed) / full:.0f}%); "
      f"killed + resumed = {killed + resumed:.1f} s ({100 * (killed + resumed) / full:.0f}% of the unbroken run)")
print(f"metric columns of frames.csv: {same} to the unbroken run's")
PY
grep "progress for --resume" "$work/unbroken.txt"
