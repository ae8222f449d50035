#!/usr/bin/env bash
# Installs what Lituya needs from Debian packages (only what is missing). Run as root or
# with sudo available.
set -euo pipefail
packages=(build-essential cmake libeigen3-dev libvtk9-dev libgmsh-dev libboost-program-options-dev
          libtomlplusplus-dev libgtest-dev gnuplot-nox)
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
