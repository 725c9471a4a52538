#!/usr/bin/env bash
# Checks a PDD_PERMISSIVE build (cmake --preset permissive; README, "Licence"):
#  1. the guard itself: a file that includes a GPL header of CGAL fails to compile with the
#     build's definitions (CGAL_LICENSE_ERROR), and the same file compiles without them (so
#     the check can fail: the build compiled every program under that guard);
#  2. every program works: pdd-mesh meshes a bundled example whole and in 8 subdomains with
#     --verify on the native kernel (the default there), --kernel cgal is refused with a message;
#     pdd-triangle -pq30a meshes, -D is refused with a message; every example program runs;
#     the Python module (when built) imports and meshes.
# Usage: scripts/check-permissive.sh BUILD_DIR   (after cmake --build --preset permissive)
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(cd "${1:?usage: scripts/check-permissive.sh BUILD_DIR}" && pwd)
cache() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt"; }
fail() { echo "check-permissive: $*" >&2; exit 1; }
[ "$(cache PDD_PERMISSIVE)" = ON ] || fail "$build is not a PDD_PERMISSIVE build"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# 1. CGAL_LICENSE_ERROR turns a GPL header into an error (and only the definition does)
printf '#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>\n#include <CGAL/Constrained_Delaunay_triangulation_2.h>\nint main() {}\n' >"$tmp/gpl.cpp"
g++ -std=c++20 -fsyntax-only "$tmp/gpl.cpp" || fail "the GPL test file does not compile at all"
if g++ -std=c++20 -fsyntax-only -DPDD_PERMISSIVE=1 -DCGAL_LICENSE_ERROR=1 "$tmp/gpl.cpp" \
  2>"$tmp/gpl.err"; then
  fail "CGAL_LICENSE_ERROR does not reject CGAL's Triangulation_2 (GPL): the guard is void"
fi
grep -q "license" "$tmp/gpl.err" || fail "the GPL header failed for another reason: $(head -3 "$tmp/gpl.err")"
echo "check-permissive: CGAL_LICENSE_ERROR rejects a GPL header (the build compiled under it)"

# 2. the programs
bin=$build/examples/drivers
for n in 1 8; do
  "$bin/pdd-mesh" examples/data/pipe.poly --max-area 1e-4 --subdomains "$n" --verify \
    --stats "$tmp/pipe$n.json" --quiet
  grep -q '"kernel": *"native"' "$tmp/pipe$n.json" || fail "pdd-mesh did not use the native kernel"
done
if "$bin/pdd-mesh" examples/data/pipe.poly --kernel cgal --quiet 2>"$tmp/cgal.err"; then
  fail "pdd-mesh --kernel cgal ran in a permissive build"
fi
grep -q "PDD_PERMISSIVE" "$tmp/cgal.err" || fail "pdd-mesh --kernel cgal: no clear message"
cp examples/data/key.poly "$tmp/"
"$bin/pdd-triangle" -pq30a0.01Q "$tmp/key.poly"
test -s "$tmp/key.1.ele" || fail "pdd-triangle wrote no key.1.ele"
if "$bin/pdd-triangle" -pDQ "$tmp/key.poly" 2>"$tmp/d.err"; then
  fail "pdd-triangle -D ran in a permissive build"
fi
grep -q "PDD_PERMISSIVE" "$tmp/d.err" || fail "pdd-triangle -D: no clear message"
for example in "$build"/examples/example_*; do
  [ -x "$example" ] || continue
  (cd "$tmp" && "$example" >/dev/null) || fail "$(basename "$example") failed"
done
if [ "$(cache PDD_PYTHON)" = ON ]; then
  py=$(cache Python_EXECUTABLE)
  PYTHONPATH="$build/python" "$py" -c "
import pdd
r = pdd.triangulate({'vertices': [[0,0],[1,0],[1,1],[0,1]], 'segments': [[0,1],[1,2],[2,3],[3,0]]}, 'pq30a0.01')
assert len(r['triangles']) > 10, r
print('check-permissive: python module', pdd.__file__, len(r['triangles']), 'triangles')"
fi
echo "check-permissive: every program of $build works without CGAL's GPL packages"
