#!/usr/bin/env bash
# Installs what FeatureRecon needs on Debian 12 with apt (run as root). Packages already present are skipped.
set -euo pipefail
packages=(
  build-essential cmake ninja-build ccache pkg-config gzip
  libcgal-dev libboost-graph-dev libeigen3-dev libgmp-dev libmpfr-dev libtbb-dev
  libgtest-dev libbenchmark-dev
  libgudhi-dev libhera-dev doxygen clang-format libpng-dev libjpeg-dev
)
if [ "${FEATURERECON_WITH_VTK:-0}" = 1 ]; then packages+=(libvtk9-dev); fi
if [ "${FEATURERECON_WITH_OPEN3D:-0}" = 1 ]; then packages+=(libopen3d-dev); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_dependencies: all ${#packages[@]} packages present"
  exit 0
fi
echo "install_dependencies: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO=sudo; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
