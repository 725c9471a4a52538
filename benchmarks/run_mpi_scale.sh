#!/usr/bin/env bash
# Reproduces the fixed-size table of benchmarks/results/scale.md (the dissertation's Tables
# 6.2/6.3 in miniature, fixed size): mpiexec -n P pdd-mesh-mpi on the bundled pipe for P = 1, 2,
# 4 ranks of one meshing thread each (oversubscribed where P exceeds the cores), the threaded
# pdd-mesh on 1 thread for reference, REPS times (default 3) back to back; time, CPU seconds of
# mpiexec and its ranks (user + sys, /usr/bin/time), speed-up over P = 1 of the same repetition,
# and the load imbalance (largest busy time / mean). Every run's files are compared with the
# threaded run's (the script stops if they differ). Raw data: benchmarks/results/scale-fixed.jsonl
# (first line: the provenance, then one line per run); the table is printed from it only.
#   bash benchmarks/run_mpi_scale.sh [BUILD_DIR] [MAX_AREA] [N] [RANKS]
# Defaults: build/release, 2e-5 (about 0.2 M triangles), N = 64, ranks "1 2 4". As root,
# Open MPI also needs OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1.
set -euo pipefail
build=${1:-build/release}
area=${2:-2e-5}
n=${3:-64}
ranks=${4:-"1 2 4"}
input=examples/data/pipe.poly
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source "$(dirname "$0")/provenance.sh"
out=benchmarks/results/scale-fixed.jsonl
provenance_json "REPS=${REPS:-3} bash benchmarks/run_mpi_scale.sh ${*@Q}" >"$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
record() { # REP P_OR_threaded: one raw data line from $tmp/run.json and $tmp/time
  python3 - "$out" "$1" "$2" "$area" "$n" "$tmp" <<'PY'
import json, sys
out, rep, p, area, n, tmp = sys.argv[1:]
j = json.load(open(f"{tmp}/run.json"))
user, system, wall = open(f"{tmp}/time").read().split()[-3:]
line = {"rep": int(rep), "program": "pdd-mesh --threads 1" if p == "threaded" else
        "pdd-mesh-mpi", "ranks": None if p == "threaded" else int(p), "max_area": area,
        "subdomains": int(n), "triangles": j["triangles"], "timings": j["timings"],
        "imbalance": j.get("imbalance"), "per_rank": j.get("per_rank"),
        "wall_seconds": float(wall), "cpu_seconds": float(user) + float(system)}
open(out, "a").write(json.dumps(line) + "\n")
PY
}
for rep in $(seq "${REPS:-3}"); do
  rm -rf "$tmp/threaded"
  /usr/bin/time -f "%U %S %e" -o "$tmp/time" "$build/examples/drivers/pdd-mesh" "$input" \
    --max-area "$area" --subdomains "$n" --threads 1 --output-per-subdomain "$tmp/threaded" \
    --stats "$tmp/run.json" -q
  record "$rep" threaded
  for p in $ranks; do
    rm -rf "$tmp/p$p"
    /usr/bin/time -f "%U %S %e" -o "$tmp/time" \
      mpiexec -n "$p" --oversubscribe --bind-to none "$build/examples/drivers/mpi/pdd-mesh-mpi" \
      "$input" --max-area "$area" --subdomains "$n" --threads 1 \
      --output-per-subdomain "$tmp/p$p" --stats "$tmp/run.json" -q
    # shellcheck disable=SC2046 # the subdomain files, in ls order
    cmp -s <(cd "$tmp/threaded" && cat $(ls)) <(cd "$tmp/p$p" && cat $(ls)) ||
      { echo "P=$p: files differ from the threaded run" >&2; exit 1; }
    record "$rep" "$p"
  done
done
PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$out" <<'PY'
import json, sys
from raw_data import read_raw_data
lines = read_raw_data(sys.argv[1])
runs = lines[1:]
print("| run | program | P ranks | triangles | path s | mesh s | total s | CPU s | speed-up "
      "| imbalance | busy s per rank |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for r in runs:
    t = r["timings"]
    one = next(x for x in runs if x["rep"] == r["rep"] and x["ranks"] == 1)
    if r["ranks"] is None:
        print(f"| {r['rep']} | {r['program']} | - | {r['triangles']} | - | - | {t['total']:.2f} | "
              f"{r['cpu_seconds']:.2f} | {one['timings']['total'] / t['total']:.2f} | - | - |")
        continue
    busy = ", ".join(f"{x['busy_s']:.2f}" for x in r["per_rank"])
    print(f"| {r['rep']} | {r['program']} | {r['ranks']} | {r['triangles']} | {t['path']:.2f} | "
          f"{t['mesh']:.2f} | {t['total']:.2f} | {r['cpu_seconds']:.2f} | "
          f"{one['timings']['total'] / t['total']:.2f} | {r['imbalance']:.3f} | {busy} |")
PY
