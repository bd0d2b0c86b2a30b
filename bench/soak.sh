#!/usr/bin/env bash
# Soak (issue 16): thousands of frames with everything switched on the way, in the window and in
# a capture; resident memory and the live GL objects (counted by asking GL) must stay flat, with
# no GL error (every frame checks; one fails the run).
#   1. `view` under Xvfb: the soak test's cycle (tests/view_script_xvfbtest.cpp, soakCycle: every
#      method with both providers, every overlay, map sizes, a resize) CYCLES times, a `stats`
#      line after each. The test itself checks the GL objects equal after every cycle and memory
#      within 16 MiB of the second cycle's.
#   2. `capture`: a FRAMES-frame walkthrough at 32x32 with seven methods and a 16-sample ground
#      truth; summary.json's "resources" has memory and GL objects after the first and last frame.
# Usage: bench/soak.sh [CYCLES] [FRAMES]   (defaults 40 and 2000; build/release must be built)
set -euo pipefail
cd "$(dirname "$0")/.."
cycles=${1:-40}
frames=${2:-2000}
build=build/release
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export MESA_SHADER_CACHE_DISABLE=true

start=$(date +%s)
FLOODLIGHT_SOAK_CYCLES=$cycles xvfb-run -a -s "-screen 0 1024x768x24 -noreset" \
    "$build/tests/view_script_xvfbtest" --gtest_filter='ViewScript.SwitchingEverything*' \
    >"$work/view.txt" 2>&1 || { tail -30 "$work/view.txt"; echo "view soak FAILED" >&2; exit 1; }
log=$build/tests/output/view_script/soak/output.txt
echo "view: $cycles cycles in $(($(date +%s) - start)) s"
grep '^stats' "$log" | sed -n '1p;2p;3p;$p'

cat >"$work/soak.json" <<JSON
{"scene": "default", "camera": {"frames": $frames, "path": "default"},
 "resolutions": [[32, 32]], "shadowMap": {"provider": "uniform", "size": 256},
 "reference": {"samples": 16, "mapSize": 256}, "saveFrames": false,
 "methods": ["hard", "pcf:3", "pcss:16/24", "vsm", "jfa-l", "jfa-e", "flood-e"]}
JSON
start=$(date +%s)
"$build/app/floodlight" capture "$work/soak.json" --out "$work/capture" >"$work/capture.txt" 2>&1 ||
    { tail -30 "$work/capture.txt"; echo "capture soak FAILED" >&2; exit 1; }
echo "capture: $frames frames in $(($(date +%s) - start)) s"
python3 - "$work/capture/summary.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))["resources"]
for k in ("firstFrame", "lastFrame"):
    s = r[k]
    print(f"  after frame {s['frame']}: resident {s['residentKiB']} KiB, GL objects {s['glObjects']}",
          {n: v for n, v in s["glObjectsByKind"].items() if v})
PY
