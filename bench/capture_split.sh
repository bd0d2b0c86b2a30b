#!/usr/bin/env bash
# Where `capture` spends its time (issue 28 item 5), before and after, in one alternating run:
# BEFORE (a floodlight binary built before the pipeline, which prints no split) and this build
# with --capture-threads 0 (synchronous) and each count in THREADS, RUNS rounds of each in turn,
# the same script. Prints every run's wall time, phase split and progress cost, then min and
# median per variant, and checks that every variant wrote the same outputs: every frame file and
# worst-frame picture byte for byte, frames.csv without its *_ms columns, summary.json without
# its times (medianFrameMs, frameTimeOverHard, medianPhaseMs), resources and phaseSplit.
# report.html embeds the times and is not compared.
# Usage: bench/capture_split.sh BEFORE [RUNS] [SCRIPT] [THREADS]
#        (defaults: 3 rounds; a 4-frame capture at 512² with medium.json's methods but flood-e,
#        1024² maps and a 64-sample ground truth; THREADS "1 2")
set -euo pipefail
cd "$(dirname "$0")/.."
before=${1:?usage: bench/capture_split.sh BEFORE [RUNS] [SCRIPT] [THREADS]}
runs=${2:-3}
script=${3:-}
threads=${4:-1 2}
bin=build/release/app/floodlight
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export MESA_SHADER_CACHE_DISABLE=true
if [ -z "$script" ]; then
    script=$work/script.json
    cat >"$script" <<'JSON'
{"scene": "default", "camera": {"frames": 4, "path": "default"}, "light": {"radius": 1.5},
 "resolutions": [[512, 512]], "shadowMap": {"provider": "uniform", "size": 1024},
 "jfaPasses": "auto", "reference": {"samples": 64, "mapSize": 1024},
 "methods": ["hard", "pcf:3", "pcf:5", "pcss:16/16", "pcss:16/24", "pcss:32/64",
             "jfa-l", "flood-l", "jfa-e"],
 "saveFrames": true}
JSON
fi
variants=(before t0)
for t in $threads; do variants+=("t$t"); done
for round in $(seq "$runs"); do
    for v in "${variants[@]}"; do
        out=$work/$v
        rm -rf "$out"
        start=$(date +%s.%N)
        if [ "$v" = before ]; then
            "$before" capture "$script" --out "$out" >"$work/log" 2>&1
        else
            "$bin" capture "$script" --out "$out" --capture-threads "${v#t}" >"$work/log" 2>&1
        fi
        wall=$(python3 -c "import sys; print(f'{float(sys.argv[2]) - float(sys.argv[1]):.2f}')" \
            "$start" "$(date +%s.%N)")
        echo "$v round $round: $wall s; $(grep -E '^phase split' "$work/log" || true)" |
            tee -a "$work/walls.txt"
        grep -E '^progress for --resume' "$work/log" | sed "s/^/  /" | tee -a "$work/walls.txt"
        [ "$round" = 1 ] && cp -r "$out" "$work/keep_$v"
    done
done
python3 - "$work/walls.txt" "${variants[@]}" <<'PY'
import re, statistics, sys
lines = open(sys.argv[1]).read().splitlines()
print("\nvariant   wall min / median (s)   outside rendering (median)   progress ms (median)")
for v in sys.argv[2:]:
    walls, outside, progress = [], [], []
    for i, l in enumerate(lines):
        m = re.match(rf"{v} round \d+: ([0-9.]+) s", l)
        if not m:
            continue
        walls.append(float(m.group(1)))
        o = re.search(r"outside rendering (\d+)%", l)
        if o: outside.append(int(o.group(1)))
        if i + 1 < len(lines):
            p = re.search(r"progress for --resume: ([0-9.]+) ms", lines[i + 1])
            if p: progress.append(float(p.group(1)))
    print(f"{v:8s}  {min(walls):6.2f} / {statistics.median(walls):6.2f}"
          f"          {str(statistics.median(outside)) + '%' if outside else '-':>6s}"
          f"                     {statistics.median(progress) if progress else '-'}")
PY
# The outputs: the first round's of every variant against the synchronous one's.
python3 - "$work" "${variants[@]}" <<'PY'
import filecmp, json, os, sys
work, variants = sys.argv[1], sys.argv[2:]
def untimed_csv(d):
    rows = [l.split(",") for l in open(os.path.join(d, "frames.csv")).read().splitlines()]
    keep = [not c.endswith("_ms") for c in rows[0]]
    return [[c for c, k in zip(r, keep) if k] for r in rows]
def untimed_summary(d):
    j = json.load(open(os.path.join(d, "summary.json")))
    j["reference"].pop("medianFrameMs", None)
    for k in ("resources", "phaseSplit"): j.pop(k, None)
    for m in j["methods"]:
        for k in ("medianFrameMs", "frameTimeOverHard", "medianPhaseMs"): m.pop(k, None)
    return j
def files(d):
    out = []
    for sub in ("frames", "report"):
        for root, _, names in os.walk(os.path.join(d, sub)):
            out += [os.path.relpath(os.path.join(root, n), d) for n in names]
    return sorted(out)
ref = os.path.join(work, "keep_t0")
for v in variants:
    d = os.path.join(work, "keep_" + v)
    same = files(d) == files(ref) and all(
        filecmp.cmp(os.path.join(d, f), os.path.join(ref, f), shallow=False) for f in files(ref))
    print(f"{v}: {len(files(d))} frame files and worst pictures "
          f"{'byte-identical' if same else 'DIFFERENT'} to t0's; "
          f"untimed CSV {'identical' if untimed_csv(d) == untimed_csv(ref) else 'DIFFERENT'}; "
          f"untimed summary {'identical' if untimed_summary(d) == untimed_summary(ref) else 'DIFFERENT'}")
PY
