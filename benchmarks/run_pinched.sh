#!/usr/bin/env bash
# A lake whose islands touch the shore and each other at single vertices (pinch vertices, issue
# 13): decoupled from its one face since 08cdcd5, meshed whole before. Runs pdd-mesh automatic
# (2 threads and 1), pdd-mesh with one subdomain (what such a domain got before: the kernel on
# the whole domain) and, when given, Triangle 1.6 on the same .poly, alternately, twice: the
# same work on both sides, one thread pinned against one (benchmarks/side_by_side.sh). With
# CRACKS = 1, every sector of the water below 60 deg between two islands touching in open water
# gets a crack: a segment from the pinch vertex along its bisector (decoupled since 033069a,
# with that corner left to the kernel's clusters; refused for N > 1 and meshed whole before).
# Usage: benchmarks/run_pinched.sh BUILD_DIR [MAX_AREA] [TRIANGLE_EXE] [CRACKS]
# KERNELS (default "cgal native"): the kernels of the automatic pdd-mesh runs (--kernel); the
# run with one subdomain uses the default kernel, CGAL's.
set -euo pipefail
build=${1:?build dir}
area=${2:-6e-5}
triangle=${3:-}
cracks=${4:-0}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
PYTHONPATH="$(dirname "$0")" python3 - "$dir/lake.poly" "$cracks" <<'PY'
import math, random, sys
from poly_file import write_poly
rng = random.Random(5)
n = 400
pts = []
for i in range(n):  # a wavy shore
    t = 2 * math.pi * i / n
    r = 10 * (1 + 0.08 * math.sin(7 * t) + 0.03 * math.sin(23 * t) + 0.01 * rng.uniform(-1, 1))
    pts.append((r * math.cos(t), r * math.sin(t)))
segs = [(i, (i + 1) % n) for i in range(n)]
holes = []
islands = []
def orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
def crosses(p, q, r, s):
    if p in (r, s) or q in (r, s):
        return False
    return orient(p, q, r) * orient(p, q, s) < 0 and orient(r, s, p) * orient(r, s, q) < 0
def island(apex, direction, size, k):  # a fan-shaped island touching `apex`; dropped if it crosses
    n0, s0 = len(pts), len(segs)
    c = pts[apex]
    poly = [apex]
    for j in range(1, k):
        a = direction - 0.6 + 1.2 * j / k + rng.uniform(-0.1, 0.1)
        rr = size * (0.6 + 0.4 * rng.random()) * math.sin(math.pi * j / k)
        pts.append((c[0] + 2 * rr * math.cos(a), c[1] + 2 * rr * math.sin(a)))
        poly.append(len(pts) - 1)
    segs.extend((poly[j], poly[(j + 1) % len(poly)]) for j in range(len(poly)))
    if any(crosses(pts[a], pts[b], pts[x], pts[y]) for a, b in segs[s0:] for x, y in segs[:s0]):
        del pts[n0:], segs[s0:]
        return
    holes.append((sum(pts[p][0] for p in poly) / len(poly), sum(pts[p][1] for p in poly) / len(poly)))
    islands.append(poly)
for i in range(0, n, 40):  # islands touching the shore
    island(i, math.atan2(pts[i][1], pts[i][0]) + math.pi, 0.6, 9)
def add_cracks(v, length):  # a crack along the bisector of each water sector < 60 deg at v
    c = pts[v]
    rays = sorted(math.atan2(pts[b if a == v else a][1] - c[1], pts[b if a == v else a][0] - c[0])
                  for a, b in segs if v in (a, b))
    for k in range(len(rays)):
        t0, t1 = rays[k], rays[(k + 1) % len(rays)]
        gap = (t1 - t0) % (2 * math.pi)
        if gap >= math.pi / 3:
            continue
        mid = t0 + gap / 2
        q = (c[0] + length * math.cos(mid), c[1] + length * math.sin(mid))
        inside = any(point_in(q, h) for h in islands)
        if inside or any(crosses(c, q, pts[x], pts[y]) for x, y in segs):
            continue
        pts.append(q)
        segs.append((v, len(pts) - 1))
def point_in(q, poly):  # even-odd test against an island's polygon (vertex ids)
    inside = False
    for j in range(len(poly)):
        a, b = pts[poly[j]], pts[poly[(j + 1) % len(poly)]]
        if (a[1] > q[1]) != (b[1] > q[1]) and q[0] < a[0] + (q[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]):
            inside = not inside
    return inside
for ch in range(5):  # three islands touching at one vertex in open water
    t = 2 * math.pi * ch / 5 + 0.3
    pts.append((5 * math.cos(t), 5 * math.sin(t)))
    v = len(pts) - 1
    island(v, t, 0.5, 7)
    island(v, t + math.pi, 0.5, 7)
    island(v, t + math.pi / 2, 0.3, 5)
    if sys.argv[2] == "1":
        add_cracks(v, 0.25)
write_poly(sys.argv[1], pts, segs, holes)
PY
# Raw data: benchmarks/results/pinched[-cracks].jsonl (first line: the provenance); the table is
# printed from it (benchmarks/side_by_side.sh: the same work on both sides, one pinned thread
# against one)
source "$(dirname "$0")/side_by_side.sh"
out=benchmarks/results/pinched$([ "$cracks" = 1 ] && echo -cracks || true).jsonl
side_by_side_begin "$out" "bash benchmarks/run_pinched.sh $*"
exe="$build/examples/drivers/pdd-mesh"
side_by_side_runs "$out" "$exe" "$dir/lake.poly" "$area" "$triangle"
side_by_side_table "$out"
