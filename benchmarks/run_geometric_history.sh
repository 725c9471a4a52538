#!/usr/bin/env bash
# Reproduces the geometric path's sections of benchmarks/results/real-geometries.md (issue 17,
# issue 37 item 5) at the current code, from ../shared/data (an absent geometry is skipped):
#   field     the user's bound or Algorithm 8.3's F on the same decomposition: the Bahamas and
#             the airfoil at the 2M bound, `--subdomains 64 --geometric-sizing on
#             --geometric-field user|8.3`, 2 threads (8.3 on the Bahamas makes tens of millions
#             of triangles and more than a GiB: a minute);
#   driver    the driver's feature cap and slope (geometric_decompose_options::first_feature_cap,
#             first_slope; no pdd-mesh option, so benchmarks/bench_geometric_options, which sets
#             them and calls pdd::generate), automatic N, 2 threads: a sweep on the Bahamas at
#             5M and the default (128, 1/32) against the old driver (64, 1/4) on the Bahamas at
#             1M, 2M and 20M, the airfoil at 300K and 1M and Texas at 300K;
#   loop_cap  `pdd-mesh --geometric-max-subdomains C` (the loop's cap) on the Bahamas at 2M and
#             5M, automatic N, 2 threads;
#   notch     the unit square with a 1e-4 x 1e-4 notch in its bottom side
#             (tests/common/test_domains.hpp's notched_square, written as a .poly here),
#             --max-area 5e-6, 1 thread: automatic, --geometric-field 8.3, --geometric-sizing
#             off --subdomains 64;
# and, for the over-refinement, the monolithic kernel (`--subdomains 1`) on every geometry and
# bound. A for about T triangles is the domain area / (T x 0.656), as run_real_geometries.sh
# computes it. Wall seconds, CPU seconds and max RSS from /usr/bin/time; mesh s from --stats.
# About 9 minutes on the project's 2-core machine (the 20M monolithic run is 2 to 3 of them).
# Raw data: benchmarks/results/geometric-history.jsonl (first line: the provenance, then one
# line per run); the tables are printed from it only.
#   bash benchmarks/run_geometric_history.sh [BUILD_DIR]
# Build first: cmake --build build/release --target pdd-mesh bench_geometric_options
set -euo pipefail
build=${1:-build/release}
data=../shared/data
exe="$build/examples/drivers/pdd-mesh"
bench="$build/benchmarks/bench_geometric_options"
for x in "$exe" "$bench"; do
  [ -x "$x" ] || {
    echo "$x is absent: cmake --build $build --target pdd-mesh bench_geometric_options" >&2
    exit 1
  }
done
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source "$(dirname "$0")/provenance.sh"
out=benchmarks/results/geometric-history.jsonl
provenance_json "bash benchmarks/run_geometric_history.sh $*" >"$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bahamas="$data/bahamas_islands.poly"
airfoil="$data/mesh2d_airfoil_3element.poly"
texas="$data/texas.poly"
# The unit square with a 1e-4 x 1e-4 notch in its bottom side, counter-clockwise.
notch="$tmp/notched_square.poly"
printf '%s\n' '8 2 0 0' '1 0 0' '2 0.5 0' '3 0.5 1e-4' '4 0.5001 1e-4' '5 0.5001 0' '6 1 0' \
  '7 1 1' '8 0 1' '8 0' '1 1 2' '2 2 3' '3 3 4' '4 4 5' '5 5 6' '6 6 7' '7 7 8' '8 8 1' '0' \
  >"$notch"

have() { # poly: present, or a message
  [ -f "$1" ] && return 0
  echo "skip $1 (absent)" >&2
  return 1
}

area_for() { # poly T: the area bound for about T triangles, as a plain decimal
  "$exe" "$1" --subdomains 1 --stats "$tmp/a.json" -q
  python3 -c "import json, sys
print('%.12f' % (json.load(open(sys.argv[1]))['area_domain'] / (float(sys.argv[2]) * 0.656)))" \
    "$tmp/a.json" "$2"
}

record() { # part label poly T max-area exit-status source: one JSON line from the run; source
  # is pdd-mesh's --stats file (.json) or bench_geometric_options' stdout (.out)
  python3 - "$out" "$@" "$tmp/time" "$tmp/err" <<'EOF'
import json, os, sys
out, part, label, poly, target, area, status, source, time_file, err_file = sys.argv[1:]
user, system, wall, rss = open(time_file).read().split()[-4:]
line = {"part": part, "label": label, "input": os.path.basename(poly), "target": target,
        "max_area": area, "exit_status": int(status), "wall_seconds": float(wall),
        "cpu_seconds": float(user) + float(system), "max_rss_kib": int(rss)}
if int(status) != 0:
    line["message"] = open(err_file).read().strip()
elif source.endswith(".json"):
    s = json.load(open(source))
    keep = ("triangles", "estimated_triangles", "subdomains", "threads", "split_points", "path",
            "plan_reason", "sizing_rounds", "estimated_over_refinement", "sizing_round_used",
            "geometric_cap", "interface_splits")
    line.update({k: s[k] for k in keep if k in s})
    line["mesh_seconds"] = s["timings"]["mesh"]
else:
    s = json.loads(open(source).read())
    line.update({k: v for k, v in s.items() if k not in ("input", "max_area", "wall_seconds")})
    line["call_seconds"] = s["wall_seconds"]  # pdd::generate alone, without reading the input
open(out, "a").write(json.dumps(line) + "\n")
EOF
  echo "$1 $2 $(basename "$3") $4 done" >&2
}

mesh() { # part label poly T max-area [pdd-mesh options]: one pdd-mesh run
  local status=0
  rm -f "$tmp/s.json"
  /usr/bin/time -f "%U %S %e %M" -o "$tmp/time" \
    "$exe" "$3" --max-area "$5" --stats "$tmp/s.json" -q "${@:6}" 2>"$tmp/err" || status=$?
  record "$1" "$2" "$3" "$4" "$5" "$status" "$tmp/s.json"
}

driver() { # part label poly T max-area cap slope: one bench_geometric_options run, 2 threads
  local status=0
  /usr/bin/time -f "%U %S %e %M" -o "$tmp/time" \
    "$bench" "$3" "$5" "$6" "$7" 2 >"$tmp/b.out" 2>"$tmp/err" || status=$?
  record "$1" "$2" "$3" "$4" "$5" "$status" "$tmp/b.out"
}

if have "$bahamas"; then
  a1=$(area_for "$bahamas" 1000000)
  a2=$(area_for "$bahamas" 2000000)
  a5=$(area_for "$bahamas" 5000000)
  a20=$(area_for "$bahamas" 20000000)
  mesh monolithic monolithic "$bahamas" 1M "$a1" --subdomains 1 --threads 1
  mesh monolithic monolithic "$bahamas" 2M "$a2" --subdomains 1 --threads 1
  mesh monolithic monolithic "$bahamas" 5M "$a5" --subdomains 1 --threads 1
  mesh monolithic monolithic "$bahamas" 20M "$a20" --subdomains 1 --threads 1
  for f in user 8.3; do
    mesh field "$f" "$bahamas" 2M "$a2" --subdomains 64 --geometric-sizing on \
      --geometric-field "$f" --threads 2
  done
  for cs in 64:1/4 64:1/32 128:1/8 128:1/32 128:0.015 256:1/32 1024:1/4; do
    driver driver "${cs%%:*} ${cs##*:}" "$bahamas" 5M "$a5" "${cs%%:*}" "${cs##*:}"
  done
  for t in 1M:"$a1" 2M:"$a2" 20M:"$a20"; do
    driver elsewhere "128 1/32" "$bahamas" "${t%%:*}" "${t##*:}" 128 1/32
    driver elsewhere "64 1/4" "$bahamas" "${t%%:*}" "${t##*:}" 64 1/4
  done
  for t in 2M:"$a2" 5M:"$a5"; do
    for c in 1024 2048 4096 8192; do
      mesh loop_cap "$c" "$bahamas" "${t%%:*}" "${t##*:}" --geometric-max-subdomains "$c" \
        --threads 2
    done
  done
fi
if have "$airfoil"; then
  a=$(area_for "$airfoil" 2000000)
  mesh monolithic monolithic "$airfoil" 2M "$a" --subdomains 1 --threads 1
  for f in user 8.3; do
    mesh field "$f" "$airfoil" 2M "$a" --subdomains 64 --geometric-sizing on \
      --geometric-field "$f" --threads 2
  done
fi
for g in "$airfoil":300K:300000 "$airfoil":1M:1000000 "$texas":300K:300000; do
  poly=${g%%:*} rest=${g#*:}
  have "$poly" || continue
  a=$(area_for "$poly" "${rest##*:}")
  mesh monolithic monolithic "$poly" "${rest%%:*}" "$a" --subdomains 1 --threads 1
  driver elsewhere "128 1/32" "$poly" "${rest%%:*}" "$a" 128 1/32
  driver elsewhere "64 1/4" "$poly" "${rest%%:*}" "$a" 64 1/4
done
mesh monolithic monolithic "$notch" 300K 5e-6 --subdomains 1 --threads 1
mesh notch automatic "$notch" 300K 5e-6 --threads 1
mesh notch "--geometric-field 8.3" "$notch" 300K 5e-6 --geometric-field 8.3 --threads 1
mesh notch "--geometric-sizing off --subdomains 64" "$notch" 300K 5e-6 --geometric-sizing off \
  --subdomains 64 --threads 1

PYTHONPATH="$(dirname "${BASH_SOURCE[0]}")" python3 - "$out" <<'EOF'
import sys
from raw_data import read_raw_data
path = sys.argv[1]
runs = read_raw_data(path, blank_line=False)[1:]
mono = {(r["input"], r["max_area"]): r["triangles"] for r in runs
        if r["part"] == "monolithic" and r["exit_status"] == 0}
names = {"bahamas_islands.poly": "Bahamas", "mesh2d_airfoil_3element.poly": "airfoil",
         "texas.poly": "Texas", "notched_square.poly": "notched square"}


def over(r):
    m = mono.get((r["input"], r["max_area"]))
    return f"{100.0 * (r['triangles'] / m - 1.0):+.2f} %" if m else "-"


def ok(r):
    return r["exit_status"] == 0


def section(part, title):
    rows = [r for r in runs if r["part"] == part]
    if rows:
        print(f"\n### {title}\n")
        read_raw_data(path)
    return rows


print("\nMonolithic kernel (--subdomains 1, 1 thread), the reference of the over-refinement:\n")
print("| geometry | T | A | triangles | wall s |")
print("|---|---|---|---|---|")
for r in (r for r in runs if r["part"] == "monolithic" and ok(r)):
    print(f"| {names[r['input']]} | {r['target']} | {r['max_area']} | {r['triangles']:,} | "
          f"{r['wall_seconds']:.2f} |")

rows = section("field", "The user's bound or Algorithm 8.3's F (2M bound, N = 64, 2 threads)")
if rows:
    print("| geometry | `--geometric-field` | subdomains | triangles | over-refinement | split points | "
          "mesh s | wall s | max RSS |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        rss = r["max_rss_kib"] / 1024
        rss = f"{rss / 1024:.2f} GiB" if rss >= 1024 else f"{rss:.0f} MiB"
        print(f"| {names[r['input']]} | {r['label']} | {r['subdomains']} | {r['triangles']:,} | {over(r)} | "
              f"{r['split_points']:,} | {r['mesh_seconds']:.2f} | {r['wall_seconds']:.2f} | "
              f"{rss} |")


def driver_table(rows):
    print("| geometry, T | feature cap | slope | path | subdomains (loop's cap) | triangles | "
          "over-refinement | split points | wall s |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if not ok(r):
            print(f"| {names[r['input']]} {r['target']} | {r['label']} | refused: "
                  f"{r['message']} |")
            continue
        cap, slope = r["label"].split()
        print(f"| {names[r['input']]} {r['target']} | {cap} | {slope} | {r['path']} | "
              f"{r['subdomains']} ({r['geometric_cap']}) | {r['triangles']:,} | {over(r)} | "
              f"{r['split_points']:,} | {r['wall_seconds']:.2f} |")
    for r in rows:
        if ok(r) and r["path"] != "geometric":
            print(f"\n{names[r['input']]} {r['target']}, cap {r['label']}: {r['plan_reason']}")


rows = section("driver", "The driver's feature cap and slope (the Bahamas at 5M, automatic N, "
               "2 threads)")
if rows:
    driver_table(rows)
rows = section("elsewhere", "The default (128, 1/32) against the old driver (64, 1/4) elsewhere")
if rows:
    driver_table(rows)

rows = section("loop_cap", "The loop's cap (the Bahamas, automatic N, 2 threads)")
if rows:
    print("| T | `--geometric-max-subdomains` | path | subdomains (loop's cap) | triangles | "
          "over-refinement | split points | wall s |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['target']} | {r['label']} | {r['path']} | {r['subdomains']} "
              f"({r['geometric_cap']}) | {r['triangles']:,} | {over(r)} | "
              f"{r['split_points']:,} | {r['wall_seconds']:.2f} |")
    for r in rows:
        if r["path"] != "geometric":
            print(f"\n{r['target']}, cap {r['label']}: {r['plan_reason']}")

rows = section("notch", "The notched square (--max-area 5e-6, 1 thread)")
if rows:
    print("| run | path | subdomains | triangles | over-refinement | split points | wall s |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['label']} | {r['path']} | {r['subdomains']} | {r['triangles']:,} | "
              f"{over(r)} | {r['split_points']:,} | {r['wall_seconds']:.2f} |")
EOF
