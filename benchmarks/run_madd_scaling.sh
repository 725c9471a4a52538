#!/usr/bin/env bash
# Reproduces benchmarks/results/madd-scaling.md (issue 36 item 3): MADD's time on one thread
# against the input's size and N, on synthetic water tiles (benchmarks/island_tile.py: a square
# with islands as holes, a tenth of them with a twin touching at a pinch vertex, so a general
# PSLG) of about 1K, 4K, 16K, 64K and 100K vertices, N = 16, 256, 4096 and 16384 (N <= the
# vertices). Each run is `pdd-decompose TILE -n N --threads 1 --stats` (its time_s: MADD
# alone, without reading the file). The fits are least squares of log(time) on log(vertices)
# for each N and on log(N) for each size: the exponents say how MADD grows. Raw data:
# benchmarks/results/madd-scaling.jsonl (first line: the provenance).
#   bash benchmarks/run_madd_scaling.sh [BUILD_DIR]   (default build/release)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
decompose="$build/examples/drivers/pdd-decompose"
[ -x "$decompose" ] || cmake --build "$build" --target pdd-decompose -j1 >/dev/null
# shellcheck source=provenance.sh source-path=SCRIPTDIR
source benchmarks/provenance.sh
out=benchmarks/results/madd-scaling.jsonl
provenance_json "bash benchmarks/run_madd_scaling.sh $*" >"$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for v in 1000 4000 16000 64000 100000; do
  python3 benchmarks/island_tile.py "$v" "$tmp/tile.poly"
  vertices=$(head -1 "$tmp/tile.poly" | cut -d' ' -f1)
  for n in 16 256 4096 16384; do
    [ "$n" -le "$v" ] || continue
    "$decompose" "$tmp/tile.poly" -n "$n" --threads 1 -q --stats "$tmp/s.json"
    python3 - "$tmp/s.json" "$v" "$vertices" "$n" >>"$out" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(json.dumps({"target_vertices": int(sys.argv[2]), "vertices": int(sys.argv[3]),
                  "N": int(sys.argv[4]), "subdomains": s["subdomains"], "time_s": s["time_s"],
                  "max_area_over_mean": s["max_area_over_mean"],
                  "min_separator_angle_deg": s["min_separator_angle_deg"],
                  "valid": s["valid"], "peak_rss_mib": s["peak_rss_mib"]}))
PY
  done
done
PYTHONPATH=benchmarks python3 - "$out" <<'PY'
import math, sys
from raw_data import read_raw_data
lines = read_raw_data(sys.argv[1])
runs = [l for l in lines if "time_s" in l]
sizes = sorted({r["vertices"] for r in runs})
ns = sorted({r["N"] for r in runs})
at = {(r["vertices"], r["N"]): r for r in runs}
def slope(points):
    if len(points) < 2:
        return None
    xs, ys = [math.log(x) for x, _ in points], [math.log(y) for _, y in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
print("MADD on one thread (s), pdd-decompose's time_s; max/mean area and smallest separator "
      "angle in brackets.\n")
print("| vertices | " + " | ".join(f"N = {n}" for n in ns) + " | exponent in N |")
print("|---:|" + "---:|" * len(ns) + "---:|")
for v in sizes:
    cells = []
    for n in ns:
        r = at.get((v, n))
        cells.append("-" if r is None else "%.3f (%.2f, %.1f deg)%s" % (
            r["time_s"], r["max_area_over_mean"], r["min_separator_angle_deg"],
            "" if r["valid"] else " INVALID"))
    e = slope([(n, at[(v, n)]["time_s"]) for n in ns if (v, n) in at])
    print(f"| {v} | " + " | ".join(cells) + " | " + ("-" if e is None else "%.2f" % e) + " |")
row = []
for n in ns:
    e = slope([(v, at[(v, n)]["time_s"]) for v in sizes if (v, n) in at])
    row.append("-" if e is None else "%.2f" % e)
print("| exponent in vertices | " + " | ".join(row) + " | |")
PY
