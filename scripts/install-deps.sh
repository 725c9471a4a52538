#!/usr/bin/env bash
# Installs the Debian 12 packages pdd needs, when any is missing (as root, or with sudo).
# clang (Clang 14) builds the sanitizer, fuzzing and ThreadSanitizer configurations; its
# sanitizer and libFuzzer runtimes are in libclang-rt-14-dev, which clang only recommends.
# llvm-14 holds llvm-symbolizer, which the sanitizer runtimes call to name the frames of a report:
# without it every frame is <null> and tests/tsan-suppressions.txt, which matches function names,
# matches nothing (neither clang nor libclang-rt-14-dev pulls it in).
# libopenmpi-dev and openmpi-bin (mpiexec) build and test the MPI backend (pdd-mesh-mpi).
# .ci/run checks before each stage that its tools are here (scripts/ci-require.sh), and
# scripts/fresh-machine-check.sh proves on a new Debian 12 root that this list is complete.
set -euo pipefail
packages=(build-essential cmake ninja-build libcgal-dev libboost-graph-dev libtbb-dev libmetis-dev
          libgtest-dev nlohmann-json3-dev libcli11-dev libmuparser-dev python3-meshio
          pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib
          clang libclang-rt-14-dev llvm-14 libopenmpi-dev openmpi-bin)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
