#!/usr/bin/env bash
# Reproduces benchmarks/results/kernel.md: the CGAL kernel alone on the bundled key and pipe
# domains at about 1M and 4M triangles (min angle 20.7 deg, area bound), one process per run,
# REPS times (default 2) in one loop (this VM's speed varies by tens of percent from minute to
# minute: the repetitions show by how much).
# Raw data: benchmarks/results/kernel.jsonl (first line: the provenance, then bench_kernel's JSON
# line of each run with the process's wall, CPU and peak memory from /usr/bin/time); the table is
# printed from it only. bench_kernel is built (cmake --build) only when it is missing.
#   bash benchmarks/run_kernel.sh [BUILD_DIR]       (default build/release)
set -euo pipefail
build=${1:-build/release}
bench="$build/benchmarks/bench_kernel"
[ -x "$bench" ] || cmake --build "$build" --target bench_kernel >/dev/null
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source "$(dirname "$0")/provenance.sh"
out=benchmarks/results/kernel.jsonl
provenance_json "REPS=${REPS:-2} bash benchmarks/run_kernel.sh $*" >"$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for rep in $(seq "${REPS:-2}"); do
  for domain in key pipe; do
    for n in 1000000 4000000; do
      /usr/bin/time -f "%U %S %e %M" -o "$tmp/time" "$bench" "$domain" "$n" >"$tmp/run.json"
      python3 - "$out" "$rep" "$n" "$tmp/run.json" "$tmp/time" <<'EOF'
import json, sys
out, rep, n, run, time_file = sys.argv[1:]
line = {"rep": int(rep), "target_triangles": int(n)}
line.update(json.load(open(run)))
user, system, wall, rss = open(time_file).read().split()[-4:]
line.update({"process_wall_seconds": float(wall),
             "process_cpu_seconds": float(user) + float(system), "max_rss_kib": int(rss)})
open(out, "a").write(json.dumps(line) + "\n")
EOF
    done
  done
done
PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$out" <<'EOF'
import json, sys
from raw_data import read_raw_data
lines = read_raw_data(sys.argv[1])
print("| rep | domain | triangles | vertices | wall s | CPU s | us / triangle (wall) "
      "| us / triangle (CPU) | min angle | peak RSS MiB |")
print("|---|---|---|---|---|---|---|---|---|---|")
for r in lines[1:]:
    t = r["triangles"]
    print(f"| {r['rep']} | {r['domain']} | {t:,} | {r['vertices']:,} | {r['seconds']:.2f} | "
          f"{r['mesh_cpu_seconds']:.2f} | {1e6 * r['seconds'] / t:.2f} | "
          f"{1e6 * r['mesh_cpu_seconds'] / t:.2f} | {r['min_angle_deg']:.2f} | "
          f"{r['peak_rss_mib']:.0f} |")
EOF
