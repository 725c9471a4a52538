#!/usr/bin/env bash
# Thread and rank scaling beyond this machine's two cores, and the kernels against Triangle 1.6 on
# a quiet machine (issues 14 and 15; results in benchmarks/results/scaling.md).
#
# usage: bash benchmarks/run_scaling.sh BIN_DIR TRIANGLE DATA_DIR OUT_DIR [MAX_THREADS]
#   BIN_DIR   folder with pdd-mesh and pdd-mesh-mpi (build/release/examples/drivers and .../mpi
#             copied side by side)
#   TRIANGLE  Triangle 1.6 built with ../shared/anchors/triangle/build.sh (a reference only)
#   DATA_DIR  folder with key.poly, pipe.poly (examples/data) and bahamas_islands.poly
#             (../shared/data)
#   OUT_DIR   one JSON statistics file per run and results.jsonl (one line per run; RESULTS=FILE
#             puts those lines elsewhere)
#   SCALING_PARTS the parts, in order (default "pipe mpi key bahamas sizes"); PIPE_AREA, KEY_AREA,
#             MPI_AREA, MPI_SUBDOMAINS override the bounds (defaults: about 16M triangles on the
#             pipe and the key, 8M for the MPI runs); THREADS="1 2 16" replaces the powers of
#             two up to MAX_THREADS (threads and ranks); MPI_SUBDOMAINS_PER_RANK=k makes the
#             scaled-size runs use k * P subdomains (default: MPI_SUBDOMAINS for every P);
#             KERNELS="native" limits the kernels of the 16M runs; the part "versus" (not in
#             the default list) runs issue 14's targets side by side, REPS times.
# Every run is one process, timed by a small Python wrapper (wall, user + system CPU seconds,
# peak RSS of the child). No mesh is written (pdd-mesh without -o; Triangle with -NEP, -Q).
set -euo pipefail
bin=$1 tri=$2 data=$3 out=$4 max_threads=${5:-16}
mkdir -p "$out"
results=${RESULTS:-$out/results.jsonl}

# timed NAME CMD...: runs CMD, appends {"run": NAME, wall_s, cpu_s, peak_rss_mib, rc} to results
timed() {
  local name=$1
  shift
  python3 - "$name" "$results" "$@" <<'EOF'
import json, resource, subprocess, sys, time
name, results, cmd = sys.argv[1], sys.argv[2], sys.argv[3:]
t = time.time()
rc = subprocess.run(cmd, stdout=subprocess.DEVNULL).returncode
wall = time.time() - t
ru = resource.getrusage(resource.RUSAGE_CHILDREN)
line = {"run": name, "wall_s": round(wall, 3), "cpu_s": round(ru.ru_utime + ru.ru_stime, 3),
        "peak_rss_mib": round(ru.ru_maxrss / 1024, 1), "rc": rc}
print(json.dumps(line), flush=True)
with open(results, "a") as f:
    f.write(json.dumps(line) + "\n")
EOF
}

threads_list() {
  if [ -n "${THREADS:-}" ]; then
    echo "$THREADS" | tr ' ' '\n'
    return
  fi
  local t=1
  while [ "$t" -le "$max_threads" ]; do
    echo "$t"
    t=$((t * 2))
  done
}

# Triangle's -a takes a plain decimal (no exponent).
decimal() { python3 -c "import sys; print(format(float(sys.argv[1]), '.12f').rstrip('0'))" "$1"; }

# 1. The kernels on one domain at about 16M triangles: Triangle, native and CGAL monolithic, then
#    decoupled with each kernel at 1, 2, 4, ... threads.
kernels_and_threads() {
  local domain=$1 area=$2
  local poly=$data/$domain.poly
  timed "$domain triangle 1" "$tri" -pq20.7048a"$(decimal "$area")"QNEP "$poly"
  for kernel in ${KERNELS:-native cgal}; do
    timed "$domain $kernel monolithic 1" "$bin/pdd-mesh" "$poly" --max-area "$area" \
      --subdomains 1 --threads 1 --kernel "$kernel" --quiet \
      --stats "$out/$domain-$kernel-mono.json"
    for t in $(threads_list); do
      timed "$domain $kernel decoupled $t" "$bin/pdd-mesh" "$poly" --max-area "$area" \
        --threads "$t" --kernel "$kernel" --quiet --stats "$out/$domain-$kernel-t$t.json"
    done
  done
}

# 2. MPI ranks (one meshing thread each), fixed size and scaled size (area / P).
mpi_ranks() {
  local area=$1 subdomains=$2
  local poly=$data/pipe.poly
  local mpirun=(mpiexec --oversubscribe --bind-to none)
  for p in $(threads_list); do
    timed "pipe mpi fixed $p" "${mpirun[@]}" -n "$p" "$bin/pdd-mesh-mpi" "$poly" \
      --max-area "$area" --subdomains "$subdomains" --threads 1 --quiet \
      --output-per-subdomain "$out/mpi-fixed-$p" --stats "$out/mpi-fixed-$p.json"
    rm -rf "$out/mpi-fixed-$p"
  done
  for p in $(threads_list); do
    local scaled n=$subdomains
    scaled=$(python3 -c "print($area * $max_threads / $p)")
    [ -z "${MPI_SUBDOMAINS_PER_RANK:-}" ] || n=$((MPI_SUBDOMAINS_PER_RANK * p))
    timed "pipe mpi scaled $p" "${mpirun[@]}" -n "$p" "$bin/pdd-mesh-mpi" "$poly" \
      --max-area "$scaled" --subdomains "$n" --threads 1 --quiet \
      --output-per-subdomain "$out/mpi-scaled-$p" --stats "$out/mpi-scaled-$p.json"
    rm -rf "$out/mpi-scaled-$p"
  done
}

# 3. Monolithic native kernel and Triangle at about 1M and 4M triangles (area / (0.656 N)).
monolithic_sizes() {
  local domain area
  for domain in pipe key; do
    for n in 1000000 4000000; do
      if [ "$domain" = pipe ]; then area=$(python3 -c "print(2.7350336659 / (0.656 * $n))")
      else area=$(python3 -c "print(5.1003783817 / (0.656 * $n))"); fi
      timed "$domain triangle $n" "$tri" -pq20.7048a"$(decimal "$area")"QNEP "$data/$domain.poly"
      timed "$domain native $n" "$bin/pdd-mesh" "$data/$domain.poly" --max-area "$area" \
        --subdomains 1 --threads 1 --kernel native --quiet --stats "$out/$domain-native-$n.json"
    done
  done
}

bahamas() {
  timed "bahamas triangle 1" "$tri" -pq20.7048a0.00002QNEP "$data/bahamas_islands.poly"
  for kernel in native cgal; do
    timed "bahamas $kernel auto 1" "$bin/pdd-mesh" "$data/bahamas_islands.poly" \
      --max-area 2e-5 --threads 1 --kernel "$kernel" --quiet --stats "$out/bahamas-$kernel-t1.json"
  done
}

# 4. Issue 14's targets side by side, REPS times (default 2): per domain Triangle, then pdd-mesh
#    with the automatic plan on 1 and 2 threads for each of VERSUS_KERNELS (default "native"):
#    the pipe and the key at 16M triangles, the Bahamas at 2e-5. One thread is pinned against
#    one thread (Triangle and pdd-mesh --threads 1 on CPU 0, --threads 2 on CPUs 0 and 1), and
#    the first line of the results is the run's provenance (benchmarks/provenance.sh).
versus_triangle() {
  local rep d kernel
  source "$(dirname "$0")/provenance.sh"
  provenance_json "SCALING_PARTS=versus REPS=${REPS:-2} VERSUS_KERNELS=\"${VERSUS_KERNELS:-native}\" bash benchmarks/run_scaling.sh $bin $tri $data $out $max_threads" >>"$results"
  for rep in $(seq "${REPS:-2}"); do
    for d in "pipe ${PIPE_AREA:-2.61e-7}" "key ${KEY_AREA:-4.86e-7}" "bahamas_islands 2e-5"; do
      set -- $d
      timed "$1 triangle 1 rep$rep" taskset -c 0 "$tri" -pq20.7048a"$(decimal "$2")"QNEP \
        "$data/$1.poly"
      for kernel in ${VERSUS_KERNELS:-native}; do
        for t in 1 2; do
          timed "$1 $kernel auto $t rep$rep" taskset -c "$([ "$t" = 1 ] && echo 0 || echo 0-1)" \
            "$bin/pdd-mesh" "$data/$1.poly" --max-area "$2" --threads "$t" --kernel "$kernel" \
            --quiet --stats "$out/$1-$kernel-auto-t$t-rep$rep.json"
        done
      done
    done
  done
}

for part in ${SCALING_PARTS:-pipe mpi key bahamas sizes}; do
  case $part in
    pipe) kernels_and_threads pipe "${PIPE_AREA:-2.61e-7}" ;;
    key) kernels_and_threads key "${KEY_AREA:-4.86e-7}" ;;
    mpi) mpi_ranks "${MPI_AREA:-5e-7}" "${MPI_SUBDOMAINS:-256}" ;;
    bahamas) bahamas ;;
    sizes) monolithic_sizes ;;
    versus) versus_triangle ;;
    *) echo "unknown part $part" >&2; exit 2 ;;
  esac
done
