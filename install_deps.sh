#!/usr/bin/env bash
# Installs everything Catena needs on Debian 12, as root. Idempotent: when every package
# is already installed it returns without touching apt. With --tests it also installs what
# only the test suite uses (clang-format, for the sources' format check).
set -euo pipefail

packages=(
  g++ make cmake pkg-config
  petsc-dev slepc-dev libopenmpi-dev openmpi-bin openssh-client libmetis-dev libhdf5-openmpi-dev
  libgtest-dev libyaml-cpp-dev libeigen3-dev
  python3 python3-h5py python3-numpy python3-matplotlib
)
if [ "${1:-}" = "--tests" ]; then
  packages+=(clang-format)
elif [ "$#" -gt 0 ]; then
  echo "install_deps: unknown argument '$1'; accepted: --tests (also install the test tools)" >&2
  exit 2
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "install_deps: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "install_deps: all packages present"
fi
