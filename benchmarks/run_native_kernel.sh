#!/usr/bin/env bash
# Reproduces benchmarks/results/native-kernel.md: Triangle 1.6, the CGAL kernel and the native
# kernel side by side, one process per run, on the bundled key and pipe domains with the same
# area bound (chosen for about N triangles at min angle 20.7048 deg), N = 1M and 4M; then
# pdd-mesh --kernel native on one thread (decoupled, automatic N, and --subdomains 1) against
# Triangle 1.6 at three area bounds, twice, in one loop (the "own passes" table).
#   bash benchmarks/run_native_kernel.sh TRIANGLE_BINARY [BUILD_DIR] [SIZES...]
# TRIANGLE_BINARY: Shewchuk's Triangle 1.6 built outside the repository, e.g.
#   bash ../shared/anchors/triangle/build.sh /tmp/triangle   (a reference only, never linked)
# Every run is pinned to CPU 0 (taskset; all of them are one thread). Process wall seconds and
# peak RSS from /usr/bin/time; CPU seconds: Triangle's whole process (user + system), the pdd
# kernels' process up to the end of meshing (bench_kernel's mesh_cpu_seconds: without its
# statistics pass), pdd-mesh's whole process; triangles and the smallest angle (Triangle: from a
# second run with -V). Triangle runs with -QNEP and pdd-mesh with --stats only: no mesh file on
# either side. Raw data: benchmarks/results/native-kernel.jsonl (first line: the provenance,
# then one line per run); the tables are printed from it only. bench_kernel is built
# (cmake --build) only when it is missing.
set -euo pipefail
triangle=${1:?usage: run_native_kernel.sh TRIANGLE_BINARY [BUILD_DIR] [SIZES...]}
build=${2:-build/release}
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source "$(dirname "$0")/provenance.sh"
out=benchmarks/results/native-kernel.jsonl
provenance_json "bash benchmarks/run_native_kernel.sh $*" >"$out"
shift $(( $# >= 2 ? 2 : 1 ))
sizes=("${@:-1000000 4000000}")
read -r -a sizes <<< "${sizes[*]}"
bench="$build/benchmarks/bench_kernel"
[ -x "$bench" ] || cmake --build "$build" --target bench_kernel >/dev/null
pdd="$build/examples/drivers/pdd-mesh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
angle=20.7048
# record PART DOMAIN PROGRAM REP [JSON_FILE] [key=value...]: one raw data line, with the
# /usr/bin/time figures of $tmp/time
record() {
  python3 - "$out" "$tmp/time" "$@" <<'EOF'
import json, sys
out, time_file, part, domain, program, rep, *rest = sys.argv[1:]
user, system, wall, rss = open(time_file).read().split()[-4:]
line = {"part": part, "domain": domain, "program": program, "rep": int(rep),
        "wall_seconds": float(wall), "process_cpu_seconds": float(user) + float(system),
        "max_rss_kib": int(rss)}
for r in rest:
    if "=" in r:
        k, v = r.split("=", 1)
        line[k] = json.loads(v) if v[:1].isdigit() else v
    else:
        line["run"] = json.load(open(r))
open(out, "a").write(json.dumps(line) + "\n")
EOF
}
triangle_run() { # PART DOMAIN REP AREA (fixed point: Triangle reads no exponents)
  /usr/bin/time -f "%U %S %e %M" -o "$tmp/time" taskset -c 0 \
    "$triangle" -pq${angle}a"$4"QNEP "$tmp/$2.poly"
  "$triangle" -pq${angle}a"$4"VNEP "$tmp/$2.poly" >"$tmp/stats"
  record "$1" "$2" "Triangle 1.6" "$3" "area=$4" \
    "triangles=$(awk '/Mesh triangles:/ {print $3}' "$tmp/stats")" \
    "min_angle_deg=$(awk '/Smallest angle:/ {print $3}' "$tmp/stats")"
}
for domain in key pipe; do
  cp "examples/data/$domain.poly" "$tmp/$domain.poly"
done
for domain in key pipe; do
  for n in "${sizes[@]}"; do
    for kernel in cgal native; do
      /usr/bin/time -f "%U %S %e %M" -o "$tmp/time" taskset -c 0 \
        "$bench" "$domain" "$n" "$angle" "$kernel" >"$tmp/run.json"
      record kernels "$domain" "$kernel" 1 "$tmp/run.json" "target_triangles=$n"
    done
    triangle_run kernels "$domain" 1 \
      "$(python3 -c "import json,sys; print('%.15f' % json.load(open(sys.argv[1]))['max_area'])" \
        "$tmp/run.json")"
  done
done
# pdd-mesh --kernel native on one thread against Triangle (the "own passes" table)
for rep in 1 2; do
  for case in "pipe 0.0000026" "pipe 0.0000011" "key 0.0000016"; do
    read -r domain area <<<"$case"
    triangle_run pdd-mesh "$domain" "$rep" "$area"
    for plan in decoupled monolithic; do
      opts=()
      [ "$plan" = monolithic ] && opts=(--subdomains 1)
      /usr/bin/time -f "%U %S %e %M" -o "$tmp/time" taskset -c 0 "$pdd" "$tmp/$domain.poly" \
        --max-area "$area" --kernel native --threads 1 "${opts[@]}" --quiet --stats "$tmp/s.json"
      record pdd-mesh "$domain" "pdd-mesh --kernel native, $plan" "$rep" "$tmp/s.json" \
        "area=$area"
    done
  done
done
PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$out" <<'EOF'
import json, sys
from raw_data import read_raw_data
lines = read_raw_data(sys.argv[1])
print("| domain | kernel | triangles | wall s | CPU s | us / triangle (CPU) | peak RSS MiB "
      "| bytes / triangle | min angle | Triangle's CPU / this CPU |")
print("|---|---|---|---|---|---|---|---|---|---|")
kern = [r for r in lines[1:] if r["part"] == "kernels"]
rows = []
for r in kern:
    if "run" in r:
        t, cpu, m = r["run"]["triangles"], r["run"]["mesh_cpu_seconds"], r["run"]["min_angle_deg"]
    else:
        t, cpu, m = r["triangles"], r["process_cpu_seconds"], r["min_angle_deg"]
    rows.append((r, t, cpu, m))
for i, (r, t, cpu, m) in enumerate(rows):
    tri = rows[i - i % 3 + 2]  # Triangle closes each group of three (cgal, native, Triangle)
    rss = r["max_rss_kib"]
    print(f"| {r['domain']} | {r['program']} | {t:,} | {r['wall_seconds']:.2f} | {cpu:.2f} | "
          f"{1e6 * cpu / t:.2f} | {rss / 1024:.0f} | {rss * 1024 / t:.0f} | {m:.2f} | "
          f"{tri[2] / cpu:.2f}x |")
print("\nOne thread, pdd-mesh --kernel native (whole process) against Triangle 1.6:\n")
print("| rep | domain, area bound | program | triangles | subdomains | wall s | CPU s "
      "| Triangle's CPU / this CPU |")
print("|---|---|---|---|---|---|---|---|")
own = [r for r in lines[1:] if r["part"] == "pdd-mesh"]
for r in own:
    t = next(x for x in own if x["rep"] == r["rep"] and x["domain"] == r["domain"]
             and x["area"] == r["area"] and x["program"] == "Triangle 1.6")
    tris = r["run"]["triangles"] if "run" in r else r["triangles"]
    sub = r["run"]["subdomains"] if "run" in r else "-"
    print(f"| {r['rep']} | {r['domain']}, {r['area']} | {r['program']} | {tris:,} | {sub} | "
          f"{r['wall_seconds']:.2f} | {r['process_cpu_seconds']:.2f} | "
          f"{t['process_cpu_seconds'] / r['process_cpu_seconds']:.2f}x |")
EOF
