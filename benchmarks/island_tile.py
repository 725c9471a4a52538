#!/usr/bin/env python3
"""Writes a synthetic water tile as a Triangle .poly file: the square [0, W]^2 with islands
(holes) on a jittered lattice, each a random polygon of 5-12 vertices, and a tenth of them with a
twin island touching it at one vertex (a pinch vertex: a general PSLG, as coastlines with touching
islands are). Deterministic for a given seed.

  python3 benchmarks/island_tile.py VERTICES OUT.poly [SEED]

The island count is chosen so that the file has about VERTICES vertices."""
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from poly_file import write_poly  # noqa: E402


def island(rng, cx, cy, r, n, start_angle):
    pts = []
    for k in range(n):
        t = start_angle + 2 * math.pi * k / n
        rr = r if k == 0 else r * rng.uniform(0.7, 1.0)
        pts.append((cx + rr * math.cos(t), cy + rr * math.sin(t)))
    return pts


def tile(vertices, seed):
    rng = random.Random(seed)
    per_island = 8.5 * 1.1 + 0.1 * 7.5  # mean vertices of an island and of its twins
    islands = max(1, int(vertices / per_island))
    side = math.ceil(math.sqrt(islands))
    w = 10.0 * side
    verts = [(0.0, 0.0), (w, 0.0), (w, w), (0.0, w)]
    segs = [(0, 1), (1, 2), (2, 3), (3, 0)]
    holes = []
    made = 0
    for j in range(side):
        for i in range(side):
            if made == islands:
                break
            made += 1
            r = rng.uniform(0.8, 1.6)
            cx = 10.0 * i + 5.0 + rng.uniform(-1.0, 1.0) - r
            cy = 10.0 * j + 5.0 + rng.uniform(-1.0, 1.0)
            loops = [island(rng, cx, cy, r, rng.randint(5, 12), 0.0)]
            if rng.random() < 0.1:  # a twin touching at the first island's vertex 0
                loops.append(island(rng, cx + 2 * r, cy, r, rng.randint(5, 10), math.pi))
            shared = None
            for loop in loops:
                ids = []
                for k, p in enumerate(loop):
                    if shared is not None and k == 0:
                        ids.append(shared)
                        continue
                    ids.append(len(verts))
                    verts.append(p)
                shared = ids[0]
                for k in range(len(ids)):
                    segs.append((ids[k], ids[(k + 1) % len(ids)]))
            holes.append((cx, cy))
            if len(loops) > 1:
                holes.append((cx + 2 * r, cy))
    return verts, segs, holes


def main():
    verts, segs, holes = tile(int(sys.argv[1]), int(sys.argv[3]) if len(sys.argv) > 3 else 1)
    write_poly(sys.argv[2], verts, segs, holes, first=1)


if __name__ == "__main__":
    main()
