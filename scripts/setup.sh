#!/usr/bin/env bash
# Installs the Debian 12 packages Floodlight builds, runs and tests with. Idempotent: does nothing
# (not even `apt-get update`) when every package is already installed.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libglfw3-dev libglm-dev libtinygltf-dev libdraco-dev libmeshoptimizer-dev libopenexr-dev
  nlohmann-json3-dev libstb-dev
  libepoxy-dev libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  libgtest-dev libbenchmark-dev libcli11-dev libembree-dev clang libclang-rt-14-dev
  xvfb xauth assimp-testmodels chromium
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

sudo=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
