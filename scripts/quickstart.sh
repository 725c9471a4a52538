#!/usr/bin/env bash
# Quick start: installs what is missing (Debian 12), builds pdd-mesh, and meshes the bundled
# pipe cross-section. Prints where the mesh, the statistics and the picture went.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build/quickstart -G Ninja -DCMAKE_BUILD_TYPE=Release -DPDD_BUILD_TESTS=OFF \
  -DPDD_BUILD_EXAMPLES=OFF -DPDD_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build/quickstart --target pdd-mesh -j "$(nproc)"
mkdir -p out
build/quickstart/examples/drivers/pdd-mesh examples/data/pipe.poly --max-area 2e-5 --verify \
  -o out/pipe.vtu --stats out/pipe.json --svg out/pipe.svg --svg-histogram out/pipe_angles.svg "$@"
echo "quickstart: mesh in $PWD/out/pipe.vtu (open with ParaView), statistics in $PWD/out/pipe.json,"
echo "quickstart: pictures in $PWD/out/pipe.svg (subdomains, separators, a zoomed inset of the" \
     "triangles) and $PWD/out/pipe_angles.svg (angle histogram)"
