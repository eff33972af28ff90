#!/usr/bin/env bash
# Installs the Debian 12 packages PolycubeHex needs. Idempotent: installs only what is missing.
set -euo pipefail

packages=(
  paraview paraview-dev python3-paraview   # ParaView 5.11 and its bundled VTK 9.2
  libopenmpi-dev libdouble-conversion-dev  # required by ParaView's CMake files
  libceres-dev libeigen3-dev               # Ceres 2.1 (and SuiteSparse's CHOLMOD), Eigen 3.4
  libtet1.5-dev                            # TetGen 1.5 (AGPL-3+)
  cmake ninja-build g++                    # build
  xvfb xauth x11-apps imagemagick          # an X server for rendering, screenshots
  clang libclang-rt-14-dev                 # libFuzzer for the fuzz test (label fuzz)
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "All Debian packages are installed."
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
echo "Installing: ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
