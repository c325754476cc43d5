#!/usr/bin/env bash
# Installs heartsim's build and test dependencies from Debian packages. Idempotent: packages
# already present are skipped, and nothing is done when everything is there.
# `scripts/install-deps.sh --fuzz` adds clang with libFuzzer and its OpenMP (scripts/fuzz.sh).
set -euo pipefail

packages=(
  build-essential cmake git pkg-config
  libeigen3-dev libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libhwy-dev
  libgtest-dev libbenchmark-dev
  libstb-dev
  libassimp-dev
  libglfw3-dev libimgui-dev libepoxy-dev libegl-dev libgl-dev libgl1-mesa-dri libegl-mesa0
  xvfb xauth
)
if [ "${1:-}" = "--fuzz" ]; then packages+=(clang libclang-rt-dev libomp-dev); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "heartsim: installing ${missing[*]}" >&2
sudo=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "heartsim: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q >&2
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}" >&2
