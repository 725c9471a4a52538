#!/usr/bin/env bash
# Builds oneTBB with ThreadSanitizer from Debian's own source package, for the tsan preset.
#
# Debian's libtbb is not built with -fsanitize=thread, so ThreadSanitizer cannot see the
# synchronisation inside it: every result a TBB worker hands to another thread looks like a data
# race (google/sanitizers#1004; oneTBB#358 and #1290: "rebuild TBB with TSan"). Hiding those
# reports takes suppressions that can also hide pdd's own races, or retries; with an
# instrumented libtbb neither is needed, and the tsan preset runs with no suppression at all.
#
# The source is Debian's package of the very libtbb-dev version installed (apt-get source, which
# `scripts/install-deps.sh --tsan-tbb` fetches into /usr/local/src/pdd-onetbb; nothing is
# downloaded here). The result is installed into build/tbb-tsan/prefix, where the tsan preset's
# TBB_DIR points, with a stamp file naming the version; a second call with the same version
# does nothing. Takes about 30 s on 2 cores.
#
# Usage: scripts/build-tsan-tbb.sh [SOURCE_ROOT]   (default /usr/local/src/pdd-onetbb)
set -euo pipefail
cd "$(dirname "$0")/.."
source_root=${1:-/usr/local/src/pdd-onetbb}
version=$(dpkg-query -W -f='${Version}' libtbb-dev)
out=$PWD/build/tbb-tsan
stamp=$out/prefix/pdd-thread-sanitizer.stamp
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "onetbb $version -fsanitize=thread" ]; then
  echo "build-tsan-tbb: oneTBB $version with ThreadSanitizer already in $out/prefix"
  exit 0
fi
source_dir=$source_root/$version/onetbb
if [ ! -f "$source_dir/CMakeLists.txt" ]; then
  echo "build-tsan-tbb: no oneTBB source for libtbb-dev $version in $source_dir;" \
    "run scripts/install-deps.sh --tsan-tbb (as root) first" >&2
  exit 1
fi
rm -rf "$out"
mkdir -p "$out"
# TBB_SANITIZE=thread is oneTBB's own switch (cmake/sanitize.cmake); tbbmalloc is not built:
# pdd does not use it. TBB_STRICT=OFF: oneTBB 2021.8's -Werror trips on Clang 14's warnings.
cmake -S "$source_dir" -B "$out/build" -G Ninja -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTBB_SANITIZE=thread \
  -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF -DTBBMALLOC_BUILD=OFF -DTBB_STRICT=OFF \
  -DCMAKE_INSTALL_PREFIX="$out/prefix" >"$out.log" 2>&1 || {
  tail -20 "$out.log" >&2
  exit 1
}
cmake --build "$out/build" -j "$(nproc)" >>"$out.log" 2>&1 || {
  tail -20 "$out.log" >&2
  exit 1
}
cmake --install "$out/build" >>"$out.log" 2>&1
echo "onetbb $version -fsanitize=thread" >"$stamp"
echo "build-tsan-tbb: oneTBB $version with ThreadSanitizer installed in $out/prefix"
