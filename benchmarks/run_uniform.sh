#!/usr/bin/env bash
# Reproduces benchmarks/results/uniform.md (the dissertation's Table 6.1 / Figures 6.7-6.10 on
# this machine): pdd-mesh on the bundled key and pipe domains, monolithic kernel vs decoupled
# with N subdomains at 1 and 2 threads, one process per run (so peak RSS is per run).
#   bash benchmarks/run_uniform.sh [BUILD_DIR] [TRIANGLES] [N list] [DOMAINS]
# Defaults: build/release, 5e6 triangles, N = 8 16 32 64 128, domains "key pipe". The last run
# of each domain writes one .vtu per subdomain (--output-per-subdomain, largest N, 2 threads) to
# compare its peak RSS with the monolithic run's. Writes JSON lines to
# benchmarks/results/uniform-<TRIANGLES>.jsonl and prints the markdown table.
set -euo pipefail
build=${1:-build/release}
target=${2:-5000000}
ns=${3:-"8 16 32 64 128"}
domains=${4:-"key pipe"}
exe="$build/examples/drivers/pdd-mesh"
cmake --build "$build" --target pdd-mesh >/dev/null
out="benchmarks/results/uniform-${target}.jsonl"
: > "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for domain in $domains; do
  # area bound for about $target triangles: mean triangle area = 0.656 A (pipeline.hpp)
  "$exe" "examples/data/$domain.poly" --subdomains 1 --stats "$tmp/a.json" -q
  area=$(/usr/bin/python3 -c "
import json; print(json.load(open('$tmp/a.json'))['area_domain'] / ($target * 0.656))")
  run() { # label N threads [extra options]
    "$exe" "examples/data/$domain.poly" --max-area "$area" --subdomains "$2" --threads "$3" \
      --stats "$tmp/s.json" -q "${@:4}"
    /usr/bin/python3 -c "
import json; j = json.load(open('$tmp/s.json')); j['domain'] = '$domain'; j['label'] = '$1'
print(json.dumps(j))" >> "$out"
    echo "$domain $1 N=$2 T=$3 done" >&2
  }
  run monolithic 1 1
  for t in 1 2; do
    for n in $ns; do run decoupled "$n" "$t"; done
  done
  rm -rf "$tmp/pieces"
  run per-subdomain "${ns##* }" 2 --output-per-subdomain "$tmp/pieces"
  rm -rf "$tmp/pieces"
done
/usr/bin/python3 benchmarks/summarize_uniform.py "$out"
