#!/usr/bin/env bash
# Reproduces benchmarks/results/native-kernel.md: Triangle 1.6, the CGAL kernel and the native
# kernel side by side, one process per run, on the bundled key and pipe domains with the same
# area bound (chosen for about N triangles at min angle 20.7048 deg), N = 1M and 4M.
#   bash benchmarks/run_native_kernel.sh TRIANGLE_BINARY [BUILD_DIR] [SIZES...]
# TRIANGLE_BINARY: Shewchuk's Triangle 1.6 built outside the repository, e.g.
#   bash ../shared/anchors/triangle/build.sh /tmp/triangle   (a reference only, never linked)
# Prints one markdown table row per run: process wall seconds and peak RSS from /usr/bin/time;
# CPU seconds: Triangle's whole process (user + system), the pdd kernels' process up to the end
# of meshing (bench_kernel's mesh_cpu_seconds: without its statistics pass); triangles and the
# smallest angle (Triangle: from a second run with -V).
set -euo pipefail
triangle=${1:?usage: run_native_kernel.sh TRIANGLE_BINARY [BUILD_DIR] [SIZES...]}
build=${2:-build/release}
shift $(( $# >= 2 ? 2 : 1 ))
sizes=("${@:-1000000 4000000}")
read -r -a sizes <<< "${sizes[*]}"
cmake --build "$build" --target bench_kernel >/dev/null
bench="$build/benchmarks/bench_kernel"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
angle=20.7048
echo "| domain | kernel | triangles | wall s | CPU s | us / triangle (CPU) | peak RSS MiB | bytes / triangle | min angle |"
echo "|---|---|---|---|---|---|---|---|---|"
row() { # domain kernel triangles timefile minangle
  read -r wall cpu rss < "$4"
  python3 -c "import sys; d,k,t,w,c,r,m=sys.argv[1:]; t=int(t); c=float(c); r=int(r)
print(f'| {d} | {k} | {t:,} | {float(w):.2f} | {c:.2f} | {1e6*c/t:.2f} | {r/1024:.0f} | {r*1024/t:.0f} | {float(m):.2f} |')" \
    "$1" "$2" "$3" "$wall" "$cpu" "$rss" "$5"
}
for domain in key pipe; do
  cp "examples/data/$domain.poly" "$tmp/$domain.poly"
  for n in "${sizes[@]}"; do
    for kernel in cgal native; do
      json=$(/usr/bin/time -f "%e %U %S %M" -o "$tmp/time" "$bench" "$domain" "$n" "$angle" "$kernel")
      cpu=$(python3 -c "import json,sys; print(json.loads(sys.argv[1])['mesh_cpu_seconds'])" "$json")
      awk -v cpu="$cpu" '{print $1, cpu, $4}' "$tmp/time" > "$tmp/t"
      tri=$(python3 -c "import json,sys; print(json.loads(sys.argv[1])['triangles'])" "$json")
      min=$(python3 -c "import json,sys; print(json.loads(sys.argv[1])['min_angle_deg'])" "$json")
      area=$(python3 -c "import json,sys; print('%.15f' % json.loads(sys.argv[1])['max_area'])" "$json")
      row "$domain" "$kernel" "$tri" "$tmp/t" "$min"
    done
    # Triangle: the same area bound (fixed-point: Triangle reads no exponents), no output files.
    /usr/bin/time -f "%e %U %S %M" -o "$tmp/time" "$triangle" -pq${angle}a${area}QNEP "$tmp/$domain.poly"
    awk '{print $1, $2 + $3, $4}' "$tmp/time" > "$tmp/t"
    stats=$("$triangle" -pq${angle}a${area}VNEP "$tmp/$domain.poly")
    tri=$(echo "$stats" | awk '/Mesh triangles:/ {print $3}')
    min=$(echo "$stats" | awk '/Smallest angle:/ {print $3}')
    row "$domain" "Triangle 1.6" "$tri" "$tmp/t" "$min"
  done
done
