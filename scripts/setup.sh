#!/usr/bin/env bash
# Installs every Debian package solidtex needs. Idempotent: does nothing when all are present.
set -euo pipefail
packages=(
  build-essential cmake pkg-config clang-format ccache
  libopencv-dev
  libopenvdb-dev libboost-iostreams-dev zlib1g-dev libblosc-dev
  libcgal-dev libgmp-dev libmpfr-dev
  libopenimageio-dev openimageio-tools libtiff-dev
  libtbb-dev libeigen3-dev libcli11-dev nlohmann-json3-dev
  libnanoflann-dev libfaiss-dev libfftw3-dev libblas-dev liblapack-dev
  libgtest-dev valgrind
  libopenmpi-dev openmpi-bin
  pybind11-dev python3-dev python3-numpy python3-scipy python3-skimage python3-pil
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
