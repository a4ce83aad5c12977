#!/usr/bin/env bash
# Installs every build, test and verification dependency from Debian bookworm packages.
# Safe to run again when they are already there.
set -euo pipefail
packages=(
  build-essential cmake
  libcgal-dev libboost-dev libgmp-dev libmpfr-dev
  libgtest-dev libbenchmark-dev libcli11-dev nlohmann-json3-dev
)
# the verifier and the solvers that read our outputs back (meshio; CalculiX for the .inp)
if [ "${QM2_WITH_VERIFIER:-0}" = 1 ]; then
  packages+=(python3-meshio python3-numpy python3-scipy python3-shapely python3-matplotlib calculix-ccx)
fi
# clang and its runtime libraries (the sanitizers, libFuzzer): the sanitizer build and the
# fuzz targets of .ci/run
if [ "${QM2_WITH_CLANG:-0}" = 1 ]; then
  packages+=(clang libclang-rt-dev)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" = 0 ] || SUDO=sudo
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
