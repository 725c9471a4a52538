#!/usr/bin/env bash
# Reproduces the scaled-size table of benchmarks/results/scale.md (the dissertation's Tables
# 6.2/6.3 in miniature, scaled size): mpiexec -n P pdd-mesh-mpi on the bundled pipe for P = 1, 2,
# 4 ranks of one meshing thread each, the mesh growing with P (max area A / P, N = N1 x P
# subdomains: the same work per rank and the same subdomain size); time per element per process
# T_e = total x P / triangles, the scaled speed-up P x T_e(1) / T_e(P) (P when the time per
# element per process stays constant), the load imbalance (largest busy time / mean), and the
# CPU seconds of the whole mpiexec and its ranks (user + sys, /usr/bin/time), also per triangle
# (what a loaded machine does not change much). The files are not kept (the MPI tests compare
# them with the threaded run's).
#   bash benchmarks/run_mpi_scaled.sh [BUILD_DIR] [MAX_AREA_AT_P1] [N_AT_P1] [RANKS] [FORMAT]
# Defaults: build/release, 4e-6 (about 1.05 M triangles at P = 1), N = 32, ranks "1 2 4", vtu. As
# root, Open MPI also needs OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1.
set -euo pipefail
build=${1:-build/release}
area=${2:-4e-6}
n1=${3:-32}
ranks=${4:-"1 2 4"}
format=${5:-vtu}
input=examples/data/pipe.poly
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| P ranks | max area | N | triangles | total s | CPU s | CPU us per triangle | T_e us | scaled speed-up | imbalance | busy s per rank |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for p in $ranks; do
  a=$(/usr/bin/python3 -c "print(f'{$area / $p:.6g}')")
  n=$((n1 * p))
  /usr/bin/time -f "%U %S" -o "$tmp/p$p.time" \
    mpiexec -n "$p" --oversubscribe --bind-to none "$build/examples/drivers/mpi/pdd-mesh-mpi" \
    "$input" --max-area "$a" --subdomains "$n" --threads 1 --format "$format" \
    --output-per-subdomain "$tmp/p$p" --stats "$tmp/p$p.json" -q
  rm -rf "$tmp/p$p"
  /usr/bin/python3 - "$tmp" "$p" "$a" "$n" <<'PY'
import json, sys
tmp, p, a, n = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
j = json.load(open(f"{tmp}/p{p}.json"))
one = json.load(open(f"{tmp}/p1.json"))
user, sys_ = (float(x) for x in open(f"{tmp}/p{p}.time").read().split())
te = j["timings"]["total"] * p / j["triangles"] * 1e6
te1 = one["timings"]["total"] / one["triangles"] * 1e6
busy = ", ".join(f"{r['busy_s']:.2f}" for r in j["per_rank"])
print(f"| {p} | {a} | {n} | {j['triangles']} | {j['timings']['total']:.2f} | {user + sys_:.1f} | "
      f"{(user + sys_) / j['triangles'] * 1e6:.2f} | {te:.2f} | {p * te1 / te:.2f} | {j['imbalance']:.3f} | {busy} |")
PY
done
