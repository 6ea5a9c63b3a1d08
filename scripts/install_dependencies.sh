#!/usr/bin/env bash
# Installs the Debian 12 packages fiberbridge needs, only those that are missing (root or sudo).
set -euo pipefail
packages=(build-essential cmake libdeal.ii-dev libboost-program-options-dev libboost-dev
          libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev gnuplot-nox clang-format
          libnlopt-cxx-dev clang libclang-rt-14-dev libomp-14-dev gmsh
          pybind11-dev python3-dev python3-numpy python3-pytest)
# clang + compiler-rt (libFuzzer, ASan/UBSan runtimes) + libomp: the sanitized fuzz build of the
# CI command (FIBERBRIDGE_FUZZ=ON, README "Two commands"). NLopt: the identify library. pybind11,
# the Python headers, numpy and pytest: the Python module (source/python) and its tests.
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
[ "$(id -u)" -ne 0 ] && SUDO=sudo
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}"
