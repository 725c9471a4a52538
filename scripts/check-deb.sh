#!/usr/bin/env bash
# Builds the Debian package of a configured and built build directory (`cpack -G DEB`,
# cmake/PddPackaging.cmake) and checks its contents: every program the build made with its man
# page, the headers (pdd/pdd.hpp and the generated pdd/version.hpp), libpdd (unless the build
# is header-only, PDD_HEADER_ONLY), the CMake package, the
# Python module where Debian's python3 finds it (when the build has one), and the control
# fields (Package, Version = project(VERSION), Depends). Prints the package's path, its Depends
# and Recommends, and exits non-zero naming what is missing.
#
# Usage: scripts/check-deb.sh BUILD_DIR      (after `cmake --build BUILD_DIR`: cpack installs
#        what the build made, and fails on a program that is not built)
# Debian packages: dpkg-dev (dpkg-shlibdeps; build-essential brings it), cmake.
set -euo pipefail
build=$(cd "${1:?usage: scripts/check-deb.sh BUILD_DIR}" && pwd)
cache() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt"; }
version=$(cache CMAKE_PROJECT_VERSION)
arch=$(dpkg --print-architecture)
deb="$build/pdd_${version}_${arch}.deb"

rm -f "$deb"
(cd "$build" && cpack -G DEB)
test -f "$deb" || { echo "check-deb: cpack made no $deb" >&2; exit 1; }
files=$(dpkg-deb -c "$deb" | awk '{print $6}' | sed 's|^\./|/|')

expected=(/usr/include/pdd/pdd.hpp /usr/include/pdd/version.hpp
          /usr/lib/cmake/pdd/pddConfig.cmake /usr/lib/cmake/pdd/pddConfigVersion.cmake
          /usr/lib/cmake/pdd/pddTargets.cmake /usr/share/doc/pdd/copyright)
# libpdd: libpdd.a, or libpdd.so with BUILD_SHARED_LIBS=ON
if [ "$(cache PDD_HEADER_ONLY)" != ON ]; then
  suffix=a
  [ "$(cache BUILD_SHARED_LIBS)" = ON ] && suffix=so
  expected+=("/usr/$(cache CMAKE_INSTALL_LIBDIR)/libpdd.$suffix")
fi
# the programs (examples/drivers/pdd_<name>.cpp, pdd-mesh-mpi with MPI) and their man pages
programs=()
if [ "$(cache PDD_BUILD_DRIVERS)" = ON ]; then
  for src in "$(cache pdd_SOURCE_DIR)"/examples/drivers/pdd_*.cpp; do
    name=${src##*/}; name=${name%.cpp}; programs+=("${name//_/-}")
  done
  [ "$(cache PDD_WITH_MPI)" = ON ] && programs+=(pdd-mesh-mpi)
fi
for exe in "${programs[@]}"; do
  expected+=("/usr/bin/$exe")
  [ "$(cache PDD_MAN_PAGES)" = ON ] && expected+=("/usr/share/man/man1/$exe.1")
done
if [ "$(cache PDD_PYTHON)" = ON ]; then
  module=$(find "$build/python" -maxdepth 1 -name 'pdd.*.so' -printf '%f\n')
  expected+=("/usr/lib/python3/dist-packages/$module")
fi

missing=0
for f in "${expected[@]}"; do
  if grep -qxF "$f" <<<"$files"; then echo "check-deb: has $f"; else
    echo "check-deb: MISSING $f" >&2; missing=1; fi
done
[ "$(dpkg-deb -f "$deb" Package)" = pdd ] || { echo "check-deb: Package is not pdd" >&2; missing=1; }
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] ||
  { echo "check-deb: Version is not $version" >&2; missing=1; }
echo "check-deb: $deb ($(grep -c . <<<"$files") entries)"
echo "Depends: $(dpkg-deb -f "$deb" Depends)"
echo "Recommends: $(dpkg-deb -f "$deb" Recommends)"
exit $missing
