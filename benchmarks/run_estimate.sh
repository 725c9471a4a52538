#!/usr/bin/env bash
# Reproduces benchmarks/results/estimate.md: pdd-mesh's up-front size estimate
# (estimated_triangles, pdd::estimate_mesh_size) against the triangles the CGAL kernel makes
# (--subdomains 1), on the shared geometries (quality only, and at a modest --max-area) and on
# corridors and spikes written to a temporary folder; then the refusal of the issue-17 needle
# with its time and peak memory (/usr/bin/time); last, the estimate's own time
# (benchmarks/bench_estimate: pdd::estimate_mesh_size alone, the fastest of 5 runs, pinned to
# CPU 0) on the bundled pipe and key and on the Bahamas. A few seconds in all.
# Raw data: benchmarks/results/estimate.jsonl (first line: the provenance, then one line per
# run); the table and the needle's line are printed from it only.
#   bash benchmarks/run_estimate.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build/release}
data=../shared/data
exe="$build/examples/drivers/pdd-mesh"
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source "$(dirname "$0")/provenance.sh"
out=benchmarks/results/estimate.jsonl
provenance_json "bash benchmarks/run_estimate.sh $*" >"$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
tri() { printf '3 2 0 0\n1 0 0\n2 1 0\n3 0.5 %s\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n' "$2" >"$tmp/$1.poly"; }
tri spike-1e2 100
tri spike-1e3 1000
tri spike-1e4 10000
printf '4 2 0 0\n1 0 0\n2 100 0\n3 100 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n' \
  >"$tmp/corridor-1x100.poly"
run() { # file max-area
  local area=()
  [ "$2" = none ] || area=(--max-area "$2")
  /usr/bin/time -f "%U %S %e %M" -o "$tmp/time" \
    "$exe" "$1" "${area[@]}" --subdomains 1 -q --stats "$tmp/s.json"
  python3 - "$out" "$1" "$2" "$tmp/s.json" "$tmp/time" <<'EOF'
import json, os, sys
out, poly, area, stats, time_file = sys.argv[1:]
j = json.load(open(stats))
user, system, wall, rss = open(time_file).read().split()[-4:]
line = {"input": os.path.basename(poly), "max_area": area,
        "estimated_triangles": j["estimated_triangles"], "triangles": j["triangles"],
        "wall_seconds": float(wall), "cpu_seconds": float(user) + float(system),
        "max_rss_kib": int(rss)}
open(out, "a").write(json.dumps(line) + "\n")
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
status=0
/usr/bin/time -f "%U %S %e %M" -o "$tmp/time" \
  "$exe" "$tmp/needle.poly" --max-area 1.48e7 -q 2>"$tmp/err" || status=$?
python3 - "$out" "$status" "$tmp/err" "$tmp/time" <<'EOF'
import json, sys
out, status, err, time_file = sys.argv[1:]
user, system, wall, rss = open(time_file).read().split()[-4:]
line = {"input": "needle.poly", "max_area": "1.48e7", "exit_status": int(status),
        "message": open(err).read().strip(), "wall_seconds": float(wall),
        "cpu_seconds": float(user) + float(system), "max_rss_kib": int(rss)}
open(out, "a").write(json.dumps(line) + "\n")
EOF
bench="$build/benchmarks/bench_estimate"
[ -x "$bench" ] || cmake --build "$build" --target bench_estimate >/dev/null
for g in examples/data/pipe.poly:1e-4 examples/data/key.poly:1e-4 \
  "$data/bahamas_islands.poly:2e-4" "$data/bahamas_islands.poly:2e-5"; do
  f="${g%%:*}"
  if [ -f "$f" ]; then
    taskset -c 0 "$bench" "$f" "${g##*:}" 5 | python3 -c '
import json, os, sys
j = json.load(sys.stdin)
j["input"] = os.path.basename(j["input"])
open(sys.argv[1], "a").write(json.dumps({"part": "estimate_time", **j}) + "\n")' "$out"
  else echo "skip $f (absent)" >&2; fi
done
PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$out" <<'EOF'
import json, sys
from raw_data import read_raw_data
lines = read_raw_data(sys.argv[1])
print("| input | --max-area | estimate | triangles made | estimate / made | wall s |")
print("|---|---|---|---|---|---|")
runs = [r for r in lines[1:] if "triangles" in r and r.get("part") != "estimate_time"]
for r in runs:
    e, t = r["estimated_triangles"], r["triangles"]
    print(f"| {r['input']} | {r['max_area']} | {e:.0f} | {t} | {e / t:.2f} | "
          f"{r['wall_seconds']:.2f} |")
ratios = [r["estimated_triangles"] / r["triangles"] for r in runs]
print(f"\nestimate / made: {min(ratios):.2f}-{max(ratios):.2f} over {len(runs)} runs\n")
for r in lines[1:]:
    if "exit_status" in r:
        print(f"{r['input']}, --max-area {r['max_area']}: exit status {r['exit_status']}, "
              f"{r['wall_seconds']:.2f} s wall, {r['cpu_seconds']:.2f} s CPU, "
              f"{r['max_rss_kib'] / 1024:.1f} MiB max RSS\n\n```\n{r['message']}\n```")
timed = [r for r in lines[1:] if r.get("part") == "estimate_time"]
if timed:
    print("\n| input | --max-area | input segments | pieces | estimate | wall ms | CPU ms |")
    print("|---|---|---|---|---|---|---|")
for r in timed:
    print(f"| {r['input']} | {r['max_area']:g} | {r['input_segments']} | {r['pieces']} | "
          f"{r['estimated_triangles']:.0f} | {1e3 * r['seconds']:.2f} | "
          f"{1e3 * r['cpu_seconds']:.2f} |")
EOF
