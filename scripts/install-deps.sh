#!/usr/bin/env bash
# Installs the Debian 12 packages pdd needs, when any is missing (as root, or with sudo).
# clang (Clang 14) builds the sanitizer, fuzzing and ThreadSanitizer configurations; its
# sanitizer and libFuzzer runtimes are in libclang-rt-14-dev, which clang only recommends.
# llvm-14 holds llvm-symbolizer, which the sanitizer runtimes call to name the frames of a report:
# without it every frame of a report is <null> (neither clang nor libclang-rt-14-dev pulls it in).
# libopenmpi-dev and openmpi-bin (mpiexec) build and test the MPI backend (pdd-mesh-mpi).
# help2man writes the programs' man pages from their --help (cmake/PddManPages.cmake).
# file: cpack's DEB generator reads the binaries' types with it to find their shared libraries
# (CPACK_DEBIAN_PACKAGE_SHLIBDEPS, cmake/PddPackaging.cmake); a minimal Debian has none.
# python3-pip and python3-venv: `pip install .` and its check (scripts/check-pip-install.sh).
# mkdocs and doxygen build the documentation site (the docs target, cmake/PddDocs.cmake);
# librsvg2-bin (rsvg-convert) is for the graded tutorial's example, which CI runs with every
# other example of the docs (scripts/run_doc_examples.py).
# .ci/run checks before each stage that its tools are here (its require function), and
# scripts/fresh-machine-check.sh proves on a new Debian 12 root that this list is complete.
#
# --tsan-tbb also fetches Debian's source package of the installed libtbb-dev into
# /usr/local/src/pdd-onetbb/<version>/onetbb (adding deb-src lines for the registries apt already
# uses, when there are none), from which scripts/build-tsan-tbb.sh builds the ThreadSanitizer
# libtbb of the tsan preset (.ci/run asks for it; README's quick start does not need it).
set -euo pipefail
packages=(build-essential cmake ninja-build libcgal-dev libboost-graph-dev libtbb-dev libmetis-dev
          libgtest-dev nlohmann-json3-dev libcli11-dev libmuparser-dev python3-meshio
          pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib
          python3-pip python3-venv mkdocs doxygen librsvg2-bin
          clang libclang-rt-14-dev llvm-14 libopenmpi-dev openmpi-bin help2man file)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
else
  echo "install-deps: installing ${missing[*]}"
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# deb-src lines mirroring the deb lines of this machine's apt sources (deb822 and one-line).
add_source_lines() {
  local f
  # only Debian's own registries: a third-party one (nodesource, say) may publish no sources
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] && [ "$f" != /etc/apt/sources.list.d/pdd-deb-src.sources ] &&
      grep -q '^URIs:.*debian' "$f" && { sed 's/^Types:.*$/Types: deb-src/' "$f"; echo; }
  done | $sudo tee /etc/apt/sources.list.d/pdd-deb-src.sources >/dev/null
  if [ -f /etc/apt/sources.list ]; then
    sed -n 's/^deb \(.*debian.*\)$/deb-src \1/p' /etc/apt/sources.list |
      $sudo tee /etc/apt/sources.list.d/pdd-deb-src.list >/dev/null
  fi
  $sudo apt-get update -qq
}

fetch_tbb_source() {
  local version dest
  version=$(dpkg-query -W -f='${Version}' libtbb-dev)
  dest=/usr/local/src/pdd-onetbb/$version
  if [ -f "$dest/onetbb/CMakeLists.txt" ]; then
    echo "install-deps: oneTBB $version source present in $dest"
    return
  fi
  apt-cache showsrc onetbb 2>/dev/null | grep -qx "Version: $version" || add_source_lines
  $sudo rm -rf "$dest"
  $sudo mkdir -p "$dest"
  (cd "$dest" && $sudo apt-get source -qq "onetbb=$version" 2>&1 | grep -v "unsandboxed" || true)
  local unpacked
  unpacked=$(find "$dest" -mindepth 1 -maxdepth 1 -type d -name 'onetbb-*' | head -n 1)
  [ -n "$unpacked" ] || { echo "install-deps: apt-get source onetbb=$version failed" >&2; exit 1; }
  $sudo mv "$unpacked" "$dest/onetbb"
  echo "install-deps: oneTBB $version source in $dest/onetbb"
}

[ "${1:-}" != "--tsan-tbb" ] || fetch_tbb_source
