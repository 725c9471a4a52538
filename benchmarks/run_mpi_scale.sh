#!/usr/bin/env bash
# Reproduces benchmarks/results/scale.md (the dissertation's Tables 6.2/6.3 in miniature, fixed
# size): mpiexec -n P pdd-mesh-mpi on the bundled pipe for P = 1, 2, 4 ranks of one meshing
# thread each (oversubscribed where P exceeds the cores), the threaded pdd-mesh on 1 thread for
# reference; time, speed-up over P = 1, and the load imbalance (largest busy time / mean).
#   bash benchmarks/run_mpi_scale.sh [BUILD_DIR] [MAX_AREA] [N] [RANKS]
# Defaults: build/release, 2e-5 (about 0.6 M triangles), N = 64, ranks "1 2 4". As root,
# Open MPI also needs OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1.
set -euo pipefail
build=${1:-build/release}
area=${2:-2e-5}
n=${3:-64}
ranks=${4:-"1 2 4"}
input=examples/data/pipe.poly
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/examples/drivers/pdd-mesh" "$input" --max-area "$area" --subdomains "$n" --threads 1 \
  --output-per-subdomain "$tmp/threaded" --stats "$tmp/threaded.json" -q
/usr/bin/python3 - "$tmp/threaded.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
print(f"threaded pdd-mesh, 1 thread: {j['triangles']} triangles, {j['timings']['total']:.2f} s")
PY
echo "| P ranks | triangles | path s | mesh s | total s | speed-up | imbalance | busy s per rank |"
echo "|---|---|---|---|---|---|---|---|"
for p in $ranks; do
  mpiexec -n "$p" --oversubscribe --bind-to none "$build/examples/drivers/mpi/pdd-mesh-mpi" \
    "$input" --max-area "$area" --subdomains "$n" --threads 1 \
    --output-per-subdomain "$tmp/p$p" --stats "$tmp/p$p.json" -q
  cmp -s <(cd "$tmp/threaded" && cat $(ls)) <(cd "$tmp/p$p" && cat $(ls)) ||
    { echo "P=$p: files differ from the threaded run" >&2; exit 1; }
  /usr/bin/python3 - "$tmp" "$p" <<'PY'
import json, sys
tmp, p = sys.argv[1], sys.argv[2]
j = json.load(open(f"{tmp}/p{p}.json"))
one = json.load(open(f"{tmp}/p1.json")) if p != "1" else j
t = j["timings"]
busy = ", ".join(f"{r['busy_s']:.2f}" for r in j["per_rank"])
print(f"| {p} | {j['triangles']} | {t['path']:.2f} | {t['mesh']:.2f} | {t['total']:.2f} | "
      f"{one['timings']['total'] / t['total']:.2f} | {j['imbalance']:.3f} | {busy} |")
PY
done
