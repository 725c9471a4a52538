#!/usr/bin/env bash
# A layered section cut by low-angle (thrust) faults (issue 13): every fault meets the layer
# interfaces at below 60 deg, so each crossing is a corner below 60 deg on segments between two
# faces. Refused for N > 1 and meshed whole before caps; since caps (madd/detail/corner_caps.hpp)
# each crossing is a cap, one subdomain, and the rest is decoupled. Runs pdd-mesh automatic
# (2 threads and 1), pdd-mesh with one subdomain (what such a domain got before) and, when given,
# Triangle 1.6 on the same .poly, alternately, twice: the same work on both sides, one thread
# pinned against one (benchmarks/side_by_side.sh).
# Usage: benchmarks/run_faulted.sh BUILD_DIR [MAX_AREA] [TRIANGLE_EXE]
# KERNELS (default "cgal native"): the kernels of the automatic pdd-mesh runs (--kernel); the
# run with one subdomain uses the default kernel, CGAL's.
set -euo pipefail
build=${1:?build dir}
area=${2:-2e-4}
triangle=${3:-}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
python3 - "$dir/faulted.poly" <<'PY'
import math, sys
W, H, step = 40.0, 10.0, 0.5
nx = int(W / step)
def interface(j):  # layer interface j (1..4): a wavy polyline from the left side to the right
    return [(i * step, 2.0 * j + 0.4 * math.sin(i * step / 3 + j)) for i in range(nx + 1)]
curves = [[(0.0, 0.0), (W, 0.0)], [(0.0, H), (W, H)]]  # bottom, top (sides added below)
curves += [interface(j) for j in range(1, 5)]
faults = [((3.0 + 11 * k, 0.0), math.radians(25 + 5 * k)) for k in range(3)]  # start, dip
fault_lines = [[p, (p[0] + H / math.tan(d), H)] for p, d in faults]
def cross(p, q, r, s):  # parameters (t on pq, u on rs) of the crossing, or None
    d = (q[0] - p[0]) * (s[1] - r[1]) - (q[1] - p[1]) * (s[0] - r[0])
    if d == 0:
        return None
    t = ((r[0] - p[0]) * (s[1] - r[1]) - (r[1] - p[1]) * (s[0] - r[0])) / d
    u = ((r[0] - p[0]) * (q[1] - p[1]) - (r[1] - p[1]) * (q[0] - p[0])) / d
    return (t, u) if 0 < t < 1 and 0 <= u <= 1 else None
pieces = []  # (polyline) after inserting the crossings into both curves
for f in fault_lines:
    cuts = [(0.0, f[0]), (1.0, f[1])]
    for c in curves[2:]:
        for i in range(len(c) - 1):
            tu = cross(f[0], f[1], c[i], c[i + 1])
            if tu:
                x = (f[0][0] + tu[0] * (f[1][0] - f[0][0]), f[0][1] + tu[0] * (f[1][1] - f[0][1]))
                c.insert(i + 1, x)
                cuts.append((tu[0], x))
                # drop the interface's vertices within 0.2 of the crossing (a GIS cleanup: a
                # vertex 0.01 beside it would be a feature of its own, 20x smaller)
                near = lambda q: math.dist(q, x) < 0.2
                if i + 2 < len(c) - 1 and near(c[i + 2]):
                    del c[i + 2]
                if i > 0 and near(c[i]):
                    del c[i]
                break
    pieces.append([x for _, x in sorted(cuts)])
for c in curves[:2]:  # the faults' ends on the bottom and top
    c[1:1] = sorted(f[0 if c[0][1] == 0 else 1] for f in fault_lines)
left = [(0.0, 0.0)] + [c[0] for c in curves[2:]] + [(0.0, H)]
right = [(W, 0.0)] + [c[-1] for c in curves[2:]] + [(W, H)]
ids, pts, segs = {}, [], set()
def vid(p):
    if p not in ids:
        ids[p] = len(pts)
        pts.append(p)
    return ids[p]
for c in curves + pieces + [left, right]:
    for a, b in zip(c, c[1:]):
        segs.add((min(vid(a), vid(b)), max(vid(a), vid(b))))
segs = sorted(segs)
with open(sys.argv[1], "w") as f:
    f.write(f"{len(pts)} 2 0 0\n")
    f.writelines(f"{i} {x!r} {y!r}\n" for i, (x, y) in enumerate(pts))
    f.write(f"{len(segs)} 0\n")
    f.writelines(f"{i} {a} {b}\n" for i, (a, b) in enumerate(segs))
    f.write("0\n")
PY
# Raw data: benchmarks/results/faulted.jsonl (first line: the provenance); the table is printed
# from it (benchmarks/side_by_side.sh: the same work on both sides, one thread pinned against one)
source "$(dirname "$0")/side_by_side.sh"
out=benchmarks/results/faulted.jsonl
side_by_side_begin "$out" "bash benchmarks/run_faulted.sh $*"
exe="$build/examples/drivers/pdd-mesh"
echo "plan: $("$build/examples/drivers/pdd-mesh" "$dir/faulted.poly" --max-area "$area" \
  --threads 2 --stats "$dir/plan.json" -q >/dev/null &&
  python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['plan_reason'])" "$dir/plan.json")"
side_by_side_runs "$out" "$exe" "$dir/faulted.poly" "$area" "$triangle"
side_by_side_table "$out"
