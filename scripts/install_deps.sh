#!/usr/bin/env bash
# Installs what plyform needs from Debian's archive (Debian 12), and nothing else.
# Safe to run repeatedly: it only calls apt-get when a package is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache gfortran clang-format
  libgtest-dev libgmock-dev libbenchmark-dev libfmt-dev libcli11-dev libeigen3-dev libmetis-dev
  libopenmpi-dev openmpi-bin
  python3 python3-matplotlib python3-numpy python3-scipy python3-vtk9
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]})); then
  echo "install_deps: installing ${missing[*]}"
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
