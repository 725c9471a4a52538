#!/usr/bin/env bash
# Reproduces benchmarks/results/kernel.md: the CGAL kernel alone on the bundled key and pipe
# domains at about 1M and 4M triangles (min angle 20.7 deg, area bound), one process per run.
#   bash benchmarks/run_kernel.sh [BUILD_DIR]       (default build/release)
set -euo pipefail
build=${1:-build/release}
cmake --build "$build" --target bench_kernel >/dev/null
for domain in key pipe; do
  for n in 1000000 4000000; do
    "$build/benchmarks/bench_kernel" "$domain" "$n"
  done
done
