#!/usr/bin/env bash
# Before/after of one change, measured in one run: builds floodlight_bench at two git revisions
# (each in its own worktree under build/revisions/, reused when present), then runs the two
# binaries alternately ROUNDS times for every method and prints, per method and revision, the
# min and median over the rounds of the bench's median frame time, and the ratio after / before.
# Usage: bench/compare_revisions.sh BEFORE AFTER ROUNDS METHOD[,METHOD...] [BENCH OPTIONS...]
# e.g.   bench/compare_revisions.sh fd2178a HEAD 3 hard,jfa-l,jfa-e,pcf,pcss \
#            --width 512 --height 512 --shadow-map-size 1024 --light-radius 1.5
# A shader change alone: BEFORE = shaders:REV runs this checkout's build/release binary with
# REV's shaders/ (--shader-dir), AFTER = shaders:HEAD with the working tree's; no builds.
set -euo pipefail
cd "$(dirname "$0")/.."
before=$1 after=$2 rounds=$3 methods=$4
shift 4
root=$PWD/build/revisions
mkdir -p "$root"
shaderArgs=() # per side: --shader-dir for shaders:REV
build() { # REV -> path of its floodlight_bench
    local rev sha dir
    rev=$1
    if [[ $rev == shaders:* ]]; then
        echo "$PWD/build/release/bench/floodlight_bench"
        return
    fi
    sha=$(git rev-parse --short "$rev")
    dir=$root/$sha
    if [ ! -d "$dir" ]; then git worktree add -q --detach "$dir" "$sha"; fi
    # The release preset, as every checkout builds it (so ccache, where set up, shares objects).
    (cd "$dir" && cmake --preset release -DFLOODLIGHT_TESTS=OFF >/dev/null &&
        cmake --build build/release --target floodlight_bench >/dev/null)
    echo "$dir/build/release/bench/floodlight_bench"
}
a=$(build "$before")
b=$(build "$after")
out=$(mktemp)
shaders=$(mktemp -d)
trap 'rm -rf "$out" "$shaders"' EXIT
shaderDir() { # REV -> the --shader-dir option for shaders:REV (none otherwise)
    local rev=${1#shaders:}
    [[ $1 == shaders:* ]] || return 0
    if [ "$rev" = HEAD ]; then echo "--shader-dir=$PWD/shaders"; return; fi
    mkdir -p "$shaders/$rev" && git archive "$rev" shaders | tar -x -C "$shaders/$rev"
    echo "--shader-dir=$shaders/$rev/shaders"
}
beforeDir=$(shaderDir "$before")
afterDir=$(shaderDir "$after")
for ((r = 1; r <= rounds; ++r)); do
    for m in ${methods//,/ }; do
        for side in before after; do
            bin=$a dir=$beforeDir
            [ "$side" = after ] && bin=$b dir=$afterDir
            ms=$(MESA_SHADER_CACHE_DISABLE=true "$bin" --method "$m" $dir "$@" |
                awk '$1 == "frame" { for (i = 1; i <= NF; ++i) if ($i == "median") print $(i + 1) }')
            echo "$m $side $ms" >>"$out"
        done
    done
    echo "round $r done" >&2
done
python3 - "$out" "$before" "$after" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
print(f"| method | {sys.argv[2]} min / median ms | {sys.argv[3]} min / median ms | after / before (medians) |")
print("|---|---|---|---|")
for m in dict.fromkeys(r[0] for r in rows):
    t = {s: [float(r[2]) for r in rows if r[0] == m and r[1] == s] for s in ("before", "after")}
    mb, ma = statistics.median(t["before"]), statistics.median(t["after"])
    print(f"| {m} | {min(t['before']):.1f} / {mb:.1f} | {min(t['after']):.1f} / {ma:.1f} | {ma / mb:.2f} |")
PY
