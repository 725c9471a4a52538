#!/usr/bin/env bash
# Reproduces the scaled-size table of benchmarks/results/scale.md (the dissertation's Tables
# 6.2/6.3 in miniature, scaled size): mpiexec -n P pdd-mesh-mpi on the bundled pipe for P = 1, 2,
# 4 ranks of one meshing thread each, the mesh growing with P (max area A / P, N = N1 x P
# subdomains: the same work per rank and the same subdomain size); time per element per process
# T_e = total x P / triangles, the scaled speed-up P x T_e(1) / T_e(P) (P when the time per
# element per process stays constant), the load imbalance (largest busy time / mean), and the
# CPU seconds of the whole mpiexec and its ranks (user + sys, /usr/bin/time), also per triangle
# (what a loaded machine does not change much). REPS times (default 3) back to back, for each of
# FORMATS. The files are not kept (the MPI tests compare them with the threaded run's). Raw
# data: benchmarks/results/scale-scaled.jsonl (first line: the provenance, then one line per
# run); the table is printed from it only.
#   bash benchmarks/run_mpi_scaled.sh [BUILD_DIR] [MAX_AREA_AT_P1] [N_AT_P1] [RANKS] [FORMATS]
# Defaults: build/release, 4e-6 (about 1.05 M triangles at P = 1), N = 32, ranks "1 2 4", vtu. As
# root, Open MPI also needs OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1.
set -euo pipefail
build=${1:-build/release}
area=${2:-4e-6}
n1=${3:-32}
ranks=${4:-"1 2 4"}
formats=${5:-vtu}
input=examples/data/pipe.poly
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source "$(dirname "$0")/provenance.sh"
out=benchmarks/results/scale-scaled.jsonl
provenance_json "REPS=${REPS:-3} bash benchmarks/run_mpi_scaled.sh ${*@Q}" >"$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for format in $formats; do
  for rep in $(seq "${REPS:-3}"); do
    for p in $ranks; do
      a=$(python3 -c "import sys; print(f'{float(sys.argv[1]) / int(sys.argv[2]):.6g}')" \
        "$area" "$p")
      n=$((n1 * p))
      /usr/bin/time -f "%U %S %e" -o "$tmp/time" \
        mpiexec -n "$p" --oversubscribe --bind-to none \
        "$build/examples/drivers/mpi/pdd-mesh-mpi" "$input" --max-area "$a" --subdomains "$n" \
        --threads 1 --format "$format" --output-per-subdomain "$tmp/out" --stats "$tmp/run.json" -q
      rm -rf "$tmp/out"
      python3 - "$out" "$tmp" "$format" "$rep" "$p" "$a" "$n" <<'PY'
import json, sys
out, tmp, fmt, rep, p, a, n = sys.argv[1:]
j = json.load(open(f"{tmp}/run.json"))
user, system, wall = open(f"{tmp}/time").read().split()[-3:]
line = {"format": fmt, "rep": int(rep), "ranks": int(p), "max_area": a, "subdomains": int(n),
        "triangles": j["triangles"], "timings": j["timings"], "imbalance": j["imbalance"],
        "per_rank": j["per_rank"], "wall_seconds": float(wall),
        "cpu_seconds": float(user) + float(system)}
open(out, "a").write(json.dumps(line) + "\n")
PY
    done
  done
done
PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$out" <<'PY'
import json, sys
from raw_data import read_raw_data
lines = read_raw_data(sys.argv[1])
runs = lines[1:]
print("| format | run | P ranks | max area | N | triangles | total s | CPU s "
      "| CPU us per triangle | T_e us | scaled speed-up | imbalance | busy s per rank |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
te = lambda r: r["timings"]["total"] * r["ranks"] / r["triangles"] * 1e6
for r in runs:
    one = next(x for x in runs if x["format"] == r["format"] and x["rep"] == r["rep"]
               and x["ranks"] == 1)
    busy = ", ".join(f"{x['busy_s']:.2f}" for x in r["per_rank"])
    print(f"| {r['format']} | {r['rep']} | {r['ranks']} | {r['max_area']} | {r['subdomains']} | "
          f"{r['triangles']} | {r['timings']['total']:.2f} | {r['cpu_seconds']:.2f} | "
          f"{r['cpu_seconds'] / r['triangles'] * 1e6:.2f} | {te(r):.2f} | "
          f"{r['ranks'] * te(one) / te(r):.2f} | {r['imbalance']:.3f} | {busy} |")
PY
