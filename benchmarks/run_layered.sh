#!/usr/bin/env bash
# Layered sections whose layers thin out (issue 36 item 1): the over-refinement of the decoupled
# path against the whole-domain mesh (pdd-mesh --subdomains 1), for requested N (4, 16) and the
# automatic plan, with the default --geometric-sizing auto (the geometric path on the faces from
# 20,000 estimated triangles, planning.min_face_path_triangles; it was the default at every size
# from 8386a1e to d0ef1d0, opt-in from d0ef1d0 to 633b68c) and with --geometric-sizing off (MADD
# from the faces alone). Inputs:
#  - wedge: a 20 x 4 section whose top layer thins from 0.5 to 0.01 over 10 units and ends at
#    1.1 deg on the top side (a cap), one full interface below (the geometry of
#    tests/pipeline/face_path_test.cpp);
#  - lenses: a 40 x 10 section, three wavy interfaces and two lens-shaped layers pinching out at
#    both ends at about 5 deg;
#  - la: Triangle's soil-layer example when LA names it (la.poly of drufat/triangle, not
#    bundled).
# Every run on 2 threads pinned to CPUs 0-1 (the whole-domain kernel uses one), nothing written
# (pdd-mesh --stats only), and Triangle 1.6 -pq20.7a<AREA> (-QNEP) when TRIANGLE_EXE is given.
# Usage: benchmarks/run_layered.sh BUILD_DIR [TRIANGLE_EXE]
# AREAS (default "0.01 0.003 0.001"): the --max-area values; REPS (default 1).
set -euo pipefail
build=${1:?build dir}
triangle=${2:-}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
PYTHONPATH="$(dirname "$0")" python3 - "$dir" <<'PY'
import math, sys
from poly_file import write_poly
out = sys.argv[1]
# wedge: the top layer between y = 0 and (0, -0.5) - (10, -0.01) - (10.5, 0)
v = [(0, 0), (10.5, 0), (20, 0), (20, -2.5), (20, -4), (0, -4), (0, -2), (0, -0.5), (10, -0.01)]
s = [(0, 1), (1, 2), (2, 3), (3, 4), (4, 5), (5, 6), (6, 7), (7, 0), (7, 8), (8, 1), (6, 3)]
write_poly(f"{out}/wedge.poly", v, s, [])
# lenses: a 40 x 10 section, interfaces at y = 2.5, 5, 7.5 (wavy), lenses inside two layers
W, H, n = 40.0, 10.0, 80
vid = {}
verts, segs = [], []
def add(p):
    if p not in vid:
        vid[p] = len(verts)
        verts.append(p)
    return vid[p]
def chain(points):
    for a, b in zip(points, points[1:]):
        segs.append((add(a), add(b)))
def wavy(y0, j):
    return [(W * i / n, y0 + 0.3 * math.sin(2 * math.pi * i / n * 3 + j)) for i in range(n + 1)]
lines = [wavy(2.5 * j, j) for j in (1, 2, 3)]
for ln in lines:
    chain(ln)
left = [(0.0, 0.0)] + [ln[0] for ln in lines] + [(0.0, H)]
right = [(W, 0.0)] + [ln[-1] for ln in lines] + [(W, H)]
chain(left)
chain(right)
chain([(0.0, 0.0), (W, 0.0)])
chain([(0.0, H), (W, H)])
for x0, x1, y in ((5.0, 25.0, 3.75), (15.0, 37.0, 8.75)):  # lens: y +- 0.6 sin(pi t)
    m = 60
    top = [(x0 + (x1 - x0) * i / m, y + 0.6 * math.sin(math.pi * i / m)) for i in range(m + 1)]
    bottom = [(x0 + (x1 - x0) * i / m, y - 0.6 * math.sin(math.pi * i / m)) for i in range(m + 1)]
    chain(top)
    chain([top[0]] + bottom[1:-1] + [top[-1]])
write_poly(f"{out}/lenses.poly", verts, segs, [])
PY
source "$(dirname "$0")/side_by_side.sh"
out=benchmarks/results/layered.jsonl
side_by_side_begin "$out" "bash benchmarks/run_layered.sh $*"
exe="$build/examples/drivers/pdd-mesh"
inputs="wedge lenses"
if [ -n "${LA:-}" ]; then
  cp "$LA" "$dir/la.poly"
  inputs="$inputs la"
fi
for rep in $(seq "${REPS:-1}"); do
  for input in $inputs; do
    for area in ${AREAS:-0.01 0.003 0.001}; do
      poly="$dir/$input.poly"
      pdd_timed "$out" "$exe" "$poly" "$input $area whole" "$rep" 1 --max-area "$area" \
        --subdomains 1
      for n in 4 16; do
        pdd_timed "$out" "$exe" "$poly" "$input $area N=$n" "$rep" 2 --max-area "$area" \
          --subdomains "$n"
        pdd_timed "$out" "$exe" "$poly" "$input $area N=$n off" "$rep" 2 --max-area "$area" \
          --subdomains "$n" --geometric-sizing off
      done
      pdd_timed "$out" "$exe" "$poly" "$input $area automatic" "$rep" 2 --max-area "$area"
      if [ -n "$triangle" ]; then
        decimal=$(python3 -c "import sys; print(format(float(sys.argv[1]), 'f').rstrip('0'))" \
          "$area")
        triangle_timed "$out" "$triangle" "$poly" "$rep" "pq20.7a$decimal"
        sed -i '$ s/"label": "Triangle 1.6/"label": "'"$input $area"' Triangle 1.6/' "$out"
      fi
    done
  done
done
PYTHONPATH="$(dirname "$0")" python3 - "$out" <<'EOF'
import json, sys
from raw_data import read_raw_data
runs = read_raw_data(sys.argv[1])[1:]
print("| rep | input | max area | run | triangles | vs whole | subdomains | path | wall s |")
print("|---|---|---|---|---|---|---|---|---|")
for r in runs:
    input_, area, run = r["label"].split(" ", 2)
    whole = next(w for w in runs if w["rep"] == r["rep"] and w["label"] == f"{input_} {area} whole")
    print("| %d | %s | %s | %s | %d | %+.1f %% | %s | %s | %.2f |" % (
        r["rep"], input_, area, run, r["triangles"],
        100.0 * (r["triangles"] / whole["triangles"] - 1), r["subdomains"], r["path"],
        r["wall_seconds"]))
EOF
