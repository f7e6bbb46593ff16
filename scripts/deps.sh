#!/usr/bin/env bash
# Installs FrameFix's build and test dependencies from Debian 12's packages, once.
# Re-running is fast: nothing is installed when every package is already there.
set -euo pipefail

PACKAGES=(
  cmake g++ make pkg-config
  libocct-modeling-algorithms-dev libocct-data-exchange-dev libocct-visualization-dev libtbb-dev
  libeigen3-dev libtet1.5-dev libsuitesparse-dev
  pybind11-dev python3-dev python3-numpy python3-pytest
  nlohmann-json3-dev libcli11-dev libgtest-dev
  freecad xvfb xauth gmsh libgmsh-dev calculix-ccx
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "framefix: installing ${#missing[@]} Debian packages: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
