#!/usr/bin/env bash
# Installs what Lituya needs from Debian packages (only what is missing). Run as root or
# with sudo available.
set -euo pipefail
packages=(build-essential cmake libeigen3-dev libgmsh-dev gmsh libboost-program-options-dev
          libtomlplusplus-dev nlohmann-json3-dev libgtest-dev gnuplot-nox zlib1g-dev)
# VTK: Debian's libvtk9-dev, unless ParaView's Python tools are installed. python3-paraview
# conflicts with python3-vtk9 (a dependency of libvtk9-dev), so installing libvtk9-dev would
# remove it; the VTK inside ParaView (paraview-dev) builds Lituya just as well.
if dpkg -s python3-paraview >/dev/null 2>&1; then
  packages+=(paraview-dev)
else
  packages+=(libvtk9-dev)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
echo "install-deps: done"
