#!/usr/bin/env bash
# Reproduces benchmarks/results/estimate.md: pdd-mesh's up-front size estimate
# (estimated_triangles, pdd::estimate_mesh_size) against the triangles the CGAL kernel makes
# (--subdomains 1), on the shared geometries (quality only, and at a modest --max-area) and on
# corridors and spikes written to a temporary folder; then the refusal of the issue-17 needle
# with its time and peak memory (/usr/bin/time). A few seconds in all.
#   bash benchmarks/run_estimate.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build/release}
data=../shared/data
exe="$build/examples/drivers/pdd-mesh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
tri() { printf '3 2 0 0\n1 0 0\n2 1 0\n3 0.5 %s\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n' "$2" >"$tmp/$1.poly"; }
tri spike-1e2 100
tri spike-1e3 1000
tri spike-1e4 10000
printf '4 2 0 0\n1 0 0\n2 100 0\n3 100 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' \
  >"$tmp/corridor-1x100.poly"
echo "| input | --max-area | estimate | triangles made | estimate / made |"
echo "|---|---|---|---|---|"
run() { # file max-area
  local area=()
  [ "$2" = none ] || area=(--max-area "$2")
  "$exe" "$1" "${area[@]}" --subdomains 1 -q --stats "$tmp/s.json"
  python3 - "$1" "$2" "$tmp/s.json" <<'EOF'
import json, os, sys
j = json.load(open(sys.argv[3]))
e, t = j["estimated_triangles"], j["triangles"]
print(f"| {os.path.basename(sys.argv[1])} | {sys.argv[2]} | {e:.0f} | {t} | {e / t:.2f} |")
EOF
}
for g in lake_superior:none lake_superior:1e-4 texas:none mesh2d_airfoil_3element:none \
  mesh2d_airfoil_3element:1e-4 guitar:none triangle_A:none bahamas_islands:2e-4; do
  f="$data/${g%%:*}.poly"
  if [ -f "$f" ]; then run "$f" "${g##*:}"; else echo "skip $f (absent)" >&2; fi
done
run "$tmp/corridor-1x100.poly" none
run "$tmp/corridor-1x100.poly" 0.01
run "$tmp/spike-1e2.poly" 0.01
run "$tmp/spike-1e3.poly" 0.1
run "$tmp/spike-1e4.poly" 1
run "$tmp/spike-1e4.poly" 100
printf '3 2 0 0\n1 0 1\n2 1 0\n3 0.5 4444444422\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n' >"$tmp/needle.poly"
echo
echo "needle, --max-area 1.48e7 (exit status, wall seconds, max RSS KiB):"
/usr/bin/time -f "%x %e s %M KiB" "$exe" "$tmp/needle.poly" --max-area 1.48e7 -q || true
