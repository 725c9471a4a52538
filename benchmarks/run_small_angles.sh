#!/usr/bin/env bash
# Reproduces benchmarks/results/small-angles.md: pdd-mesh on shared geometries with input angles
# below 60 deg (shielded, dissertation 8.1) at about TRIANGLES triangles, the monolithic kernel
# vs the decoupled pipeline with N subdomains on THREADS threads, one process per run.
#   bash benchmarks/run_small_angles.sh [BUILD_DIR] [TRIANGLES] [N] [THREADS] [GEOMETRIES]
# Defaults: build/release, 2e6, N = 64, 2 threads, "lake_superior texas guitar" from
# ../shared/data (about a minute). The Bahamas (the largest closed-loop geometry) is a separate
# run of about half an hour: ... 2000000 64 2 bahamas_islands. A decoupled run whose decoupling
# path has more than 2 split points per planned triangle (bahamas: k is held at lfs_min = 1.1e-6
# by a 1.9e-6 segment) streams its subdomain meshes to .vtu files in a temporary folder instead
# of merging them in memory; its statistics come from pdd::statistics_sink. Writes JSON lines
# to benchmarks/results/small-angles-<TRIANGLES>[-<GEOMETRIES>].jsonl (the suffix when
# GEOMETRIES is given; first line: the provenance, benchmarks/provenance.sh) and prints the
# markdown table from it only (benchmarks/summarize_small_angles.py).
set -euo pipefail
build=${1:-build/release}
target=${2:-2000000}
n=${3:-64}
threads=${4:-2}
geometries=${5:-"lake_superior texas guitar"}
suffix=${5:+-${5// /_}}
data=../shared/data
exe="$build/examples/drivers/pdd-mesh"
cmake --build "$build" --target pdd-mesh pdd-decompose >/dev/null
out="benchmarks/results/small-angles-${target}${suffix}.jsonl"
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source "$(dirname "$0")/provenance.sh"
provenance_json "bash benchmarks/run_small_angles.sh $*" >"$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for g in $geometries; do
  poly="$data/$g.poly"
  [ -f "$poly" ] || { echo "skip $g: $poly is absent" >&2; continue; }
  # area bound for about $target triangles: mean triangle area = 0.656 A (pipeline.hpp)
  "$exe" "$poly" --subdomains 1 --stats "$tmp/a.json" -q
  area=$(/usr/bin/python3 -c "
import json; print(json.load(open('$tmp/a.json'))['area_domain'] / ($target * 0.656))")
  run() { # label N [extra options]
    local t0 t1
    t0=$(date +%s.%N)
    "$exe" "$poly" --max-area "$area" --subdomains "$2" --threads "$threads" \
      --stats "$tmp/s.json" -q "${@:3}"
    t1=$(date +%s.%N)
    /usr/bin/python3 -c "
import json; j = json.load(open('$tmp/s.json')); j['domain'] = '$g'; j['label'] = '$1'
j['process_seconds'] = $t1 - $t0; j['max_area'] = $area
print(json.dumps(j))" >> "$out"
    echo "$g $1 N=$2 T=$threads done" >&2
  }
  run monolithic 1 --verify
  # the size of the decoupling path decides where the decoupled meshes go
  "$build/examples/drivers/pdd-decompose" "$poly" --subdomains "$n" --threads "$threads" \
    --no-smoothing --max-area "$area" --stats "$tmp/d.json" -q
  split=$(/usr/bin/python3 -c "
import json; print(json.load(open('$tmp/d.json')).get('split_points', 0))")
  if [ "$split" -gt $((2 * target)) ]; then
    run decoupled-streamed "$n" --output-per-subdomain "$tmp/pieces"
    rm -rf "$tmp/pieces"
  else
    run decoupled "$n" --verify
  fi
done
PYTHONPATH="$(dirname "$0")" /usr/bin/python3 benchmarks/summarize_small_angles.py "$out"
