#!/usr/bin/env bash
# Window playback (issue 15): floodlight view, hard shadows, default scene (its characters walk and wave),
# 512x512, 90 frames; animations playing (all) against held at rest (none); 3 runs each,
# alternating; median loop and render ms over frames 10..89.
set -euo pipefail
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$(dirname "$0")/.."
for r in 1 2 3; do
  for a in all none; do
    MESA_SHADER_CACHE_DISABLE=true xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
      build/release/app/floodlight view --method hard --width 512 --height 512 --frames 90 \
      --stats-every 0 --animation $a --fps-log "$work/fps_${a}_$r.csv" --screenshot-dir "$work" >/dev/null 2>&1
    python3 - "$work/fps_${a}_$r.csv" $a $r <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))[10:]
loop = statistics.median(float(x["loop_ms"]) for x in rows)
render = statistics.median(float(x["render_ms"]) for x in rows)
print(f"run {sys.argv[3]} animation {sys.argv[2]}: loop {loop:.1f} ms ({1000/loop:.1f} FPS), render {render:.1f} ms")
PY
  done
done
