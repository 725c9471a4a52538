#!/usr/bin/env bash
# Dense features (issue 13; benchmarks/results/dense-features.md): a 4 x 4 square with a dangling
# square spiral of cracks joined to a corner at 18.4 deg (pdd::test::spiral_from_a_corner() of
# tests/common/dense_features.hpp, written here as spiral.poly). pdd-mesh automatic at 2 and 1
# threads, pdd-mesh with one subdomain, and, when given, Triangle 1.6 on the same .poly, twice,
# the same work on both sides (benchmarks/side_by_side.sh).
# Usage: benchmarks/run_dense_features.sh BUILD_DIR [MAX_AREA] [TRIANGLE_EXE]
# KERNELS (default "cgal native"): the kernels of the automatic pdd-mesh runs (--kernel); the
# run with one subdomain uses the default kernel, CGAL's.
set -euo pipefail
build=${1:?build dir}
area=${2:-5e-6}
triangle=${3:-}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cat >"$dir/spiral.poly" <<'POLY'
8 2 0 1
0 0 0 1
1 4 0 1
2 4 4 1
3 0 4 1
4 1 1 2
5 3 1 2
6 3 3 2
7 1 3 2
8 1
0 0 1 1
1 1 2 1
2 2 3 1
3 3 0 1
4 3 4 2
5 4 5 2
6 5 6 2
7 6 7 2
0
POLY
source "$(dirname "$0")/side_by_side.sh"
out=benchmarks/results/dense-features.jsonl
side_by_side_begin "$out" "bash benchmarks/run_dense_features.sh $*"
exe="$build/examples/drivers/pdd-mesh"
side_by_side_runs "$out" "$exe" "$dir/spiral.poly" "$area" "$triangle"
side_by_side_table "$out"
