#!/usr/bin/env bash
# Reproduces benchmarks/results/resume.md (issue 40): pdd-mesh --output-per-subdomain on the
# bundled pipe, a clean run against a run killed with SIGKILL at FRACTION of the clean run's wall
# time and resumed (--resume); prints the wall time of each, the pieces kept and meshed, and
# whether the resumed directory equals the clean one file for file (diff -r).
#   bash benchmarks/run_resume.sh [BUILD_DIR] [MAX_AREA] [N] [FORMAT] [FRACTION]
# Defaults: build/release, 5e-7 (8.3M triangles), 64 subdomains, binary, 0.8.
set -euo pipefail
build=${1:-build/release}
area=${2:-5e-7}
n=${3:-64}
format=${4:-binary}
fraction=${5:-0.8}
exe="$build/examples/drivers/pdd-mesh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
options=(examples/data/pipe.poly --max-area "$area" --subdomains "$n" --format "$format" -q)
now() { date +%s.%N; }
t0=$(now)
"$exe" "${options[@]}" --output-per-subdomain "$tmp/clean"
clean=$(echo "$(now) - $t0" | bc)
kill_at=$(echo "$clean * $fraction" | bc)
timeout -s KILL "$kill_at" "$exe" "${options[@]}" --output-per-subdomain "$tmp/run" || true
t0=$(now)
"$exe" "${options[@]}" --output-per-subdomain "$tmp/run" --resume --stats "$tmp/r.json"
resumed=$(echo "$(now) - $t0" | bc)
same=no
diff -r "$tmp/clean" "$tmp/run" >/dev/null && same=yes
/usr/bin/python3 -c "
import json; j = json.load(open('$tmp/r.json'))
print(f'| {j[\"triangles\"]} | {$n} | $format | {$clean:.2f} | {$kill_at:.2f} | {$resumed:.2f} '
      f'| {j[\"pieces_kept\"]} | {j[\"pieces_meshed\"]} | $same |')"
