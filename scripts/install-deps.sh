#!/usr/bin/env bash
# Installs the Debian packages stitch needs, and any packages given as arguments (the sanitizer
# and fuzzing scripts add clang's). Idempotent: does nothing when all are present.
set -euo pipefail
packages=(
  build-essential cmake ccache pkg-config
  libeigen3-dev libosd-dev libtbb-dev libfmt-dev nlohmann-json3-dev libcli11-dev libnlopt-cxx-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libepoxy-dev libegl-dev libegl1-mesa-dev libgl-dev libgbm-dev libosmesa6-dev libgl1-mesa-dri
  libglfw3-dev libimgui-dev libstb-dev
  libtinygltf-dev libocct-data-exchange-dev libocct-modeling-algorithms-dev
  libocct-modeling-data-dev libocct-foundation-dev
  pybind11-dev python3-dev python3-numpy python3-pytest
  xvfb xauth gnuplot-nox
  freecad-python3
  blender
)
packages+=("$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "stitch: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get -o DPkg::Lock::Timeout=600 update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get -o DPkg::Lock::Timeout=600 install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
