#!/usr/bin/env bash
# Issue 42 item 3: `cmake --install` puts the binary where a package would, and the installed
# binary, run from an empty folder with no source tree in reach, renders what the build tree's
# binary renders (the built-in scene and the shaders are inside it).
# Usage: install_relocatable.sh BUILD_DIR BUILD_TREE_BINARY WORK_DIR
set -euo pipefail
build=$1 built=$2 work=$3
rm -rf "$work"
mkdir -p "$work/prefix" "$work/empty" "$work/reference"
cmake --install "$build" --prefix "$work/prefix" >"$work/install.log"
installed="$work/prefix/bin/floodlight"
for f in "$installed" "$work/prefix/share/floodlight/assets/default.glb" \
         "$work/prefix/share/floodlight/shaders/bindings.glsl"; do
  [[ -e "$f" ]] || { echo "not installed: $f"; exit 1; }
done
args=(render --width 64 --height 64 --shadow-map-size 256 --method pcss --out .)
(cd "$work/reference" && "$built" "${args[@]}" >log.txt)
# env -i: nothing from this environment (no FLOODLIGHT_* variables, no source-tree paths).
# The sanitizer build's options pass through (Mesa's driver leaks at exit: ctest turns leak
# checking off for every GL test).
(cd "$work/empty" && env -i PATH=/usr/bin:/bin MESA_SHADER_CACHE_DISABLE=true \
   ${ASAN_OPTIONS:+ASAN_OPTIONS=$ASAN_OPTIONS} "$installed" "${args[@]}" >log.txt)
for f in frame.png frame.visibility.png frame.exr; do
  cmp "$work/reference/$f" "$work/empty/$f" || { echo "$f differs from the build tree's"; exit 1; }
done
grep -q "default.glb (built in)" "$work/empty/log.txt" || { cat "$work/empty/log.txt"; exit 1; }
echo "installed binary renders what the build tree's renders: frame.png, .visibility.png, .exr"
