#!/usr/bin/env bash
# Frames per second of `floodlight view` for every shadow method on the default scene (issue 7):
# a --script presses M through the methods, --fps-log records each frame, and the summary takes,
# per method, the frames after the first WARMUP (shader compilation on first use) of each visit.
# Usage: bench/view_fps.sh [BINARY] [RUNS] [SIZE] [EXTRA VIEW OPTIONS...]
# (needs xvfb-run; prints a markdown table). E.g. --reference-samples 16 keeps the reference
# method (64 shadow maps per frame by default) from dominating the run time.
set -euo pipefail
bin=${1:-build/release/app/floodlight}
runs=${2:-3}
size=${3:-512}
shift $(($# < 3 ? $# : 3))
frames=10 warmup=3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The method list as the CLI accepts it, e.g. {hard,jfa-l,...}: one visit each.
methods=$("$bin" view --help | grep -o -- '--method TEXT:{[^}]*}' | sed 's/.*{//; s/}//')
count=$(tr ',' '\n' <<<"$methods" | wc -l)
{
    echo "wait $frames"
    for ((i = 1; i < count; ++i)); do printf 'key M\nwait %d\n' "$frames"; done
} >"$work/fps.script"
for ((r = 1; r <= runs; ++r)); do
    MESA_SHADER_CACHE_DISABLE=true xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$bin" view \
        --width "$size" --height "$size" --stats-every 0 --script "$work/fps.script" \
        --fps-log "$work/run$r.csv" --screenshot-dir "$work" "$@" >/dev/null
    echo "run $r done" >&2
done
# Per run and method: median loop time (render + present + HUD + swap) and median render time
# (the renderer's per-phase timer) over the measured frames; then min and median over the runs.
python3 - "$warmup" "$work"/run*.csv <<'PY'
import csv, statistics, sys
warmup, files = int(sys.argv[1]), sys.argv[2:]
loops, renders, order = {}, {}, []
for f in files:
    seen, prev, run_loop, run_render = {}, None, {}, {}
    for row in csv.DictReader(open(f)):
        m = row["method"]
        if m != prev:
            seen[m], prev = 0, m
        seen[m] += 1
        if seen[m] <= warmup or row["stats"] == "1":
            continue
        if m not in order:
            order.append(m)
        run_loop.setdefault(m, []).append(float(row["loop_ms"]))
        run_render.setdefault(m, []).append(float(row["render_ms"]))
    for m in run_loop:
        loops.setdefault(m, []).append(statistics.median(run_loop[m]))
        renders.setdefault(m, []).append(statistics.median(run_render[m]))
print("| method | FPS (median of runs) | FPS (best run) | loop ms, median | render ms, median |")
print("|---|---|---|---|---|")
for m in order:
    med = statistics.median(loops[m])
    print(f"| {m} | {1000 / med:.2f} | {1000 / min(loops[m]):.2f} | {med:.1f} | "
          f"{statistics.median(renders[m]):.1f} |")
PY
