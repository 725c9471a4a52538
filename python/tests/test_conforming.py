"""pytest tests of Triangle's -D (conforming Delaunay) and -S (a Steiner point budget) through
pdd.triangulate: the exact global Delaunay property, the domain's area, the q and a bounds, the
markers of split segments, the count of Steiner points."""
from fractions import Fraction

import numpy as np
import pytest

import pdd


def notch():
    """[0,2]x[0,1] with a narrow notch from the top down to (1, 0.05): the vertex (1.03, 0.6) of
    its right wall lies in the diametral circle of the left wall (the CDT is not Delaunay).
    The notch's walls have marker 5, the rest 1."""
    v = np.array([[0, 0], [2, 0], [2, 1], [1.05, 1], [1.03, 0.6], [1, 0.05], [0.95, 1], [0, 1]])
    s = np.array([[i, (i + 1) % 8] for i in range(8)])
    m = np.array([[5 if 3 <= i <= 5 else 1] for i in range(8)], dtype=np.int32)
    return dict(vertices=v, segments=s, segment_markers=m)


def holed_square():
    v = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [.4, .4], [.6, .4], [.6, .6], [.4, .6]], dtype=float)
    s = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]])
    return dict(vertices=v, segments=s, holes=np.array([[.5, .5]]))


def polygon_area(v):
    x, y = v[:, 0], v[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - y * np.roll(x, -1)))


def mesh_area(r):
    v, t = r["vertices"], r["triangles"]
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    return 0.5 * float(np.sum((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])))


def in_circle(a, b, c, d):
    """Exact sign of the in-circle determinant (> 0: d strictly inside the circle of the
    counter-clockwise a, b, c), in rationals: every double is a Fraction exactly."""
    a, b, c, d = ([Fraction(x) for x in p] for p in (a, b, c, d))
    rows = [(p[0] - d[0], p[1] - d[1]) for p in (a, b, c)]
    m = [(x, y, x * x + y * y) for x, y in rows]
    det = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
           - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
           + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    return (det > 0) - (det < 0)


def delaunay_violations(r):
    """Triangles with a vertex of the mesh strictly inside their circumcircle: a float test
    picks the candidates (a generous margin), the exact test decides."""
    v, t = r["vertices"], r["triangles"]
    bad = 0
    for tri in t:
        a, b, c = v[tri]
        ax, ay = (a - v).T
        bx, by = (b - v).T
        cx, cy = (c - v).T
        det = (ax * ax + ay * ay) * (bx * cy - by * cx) - (bx * bx + by * by) * (ax * cy - ay * cx) \
            + (cx * cx + cy * cy) * (ax * by - ay * bx)
        cand = np.nonzero(det > -1e-9)[0]
        if any(k not in tri and in_circle(a, b, c, v[k]) > 0 for k in cand):
            bad += 1
    return bad


def test_p_alone_is_not_delaunay_on_the_notch_but_pD_is():
    g = notch()
    p = pdd.triangulate(g, "p")
    assert delaunay_violations(p) > 0  # the test can fail: -p alone is constrained Delaunay only
    d = pdd.triangulate(g, "pD")
    assert delaunay_violations(d) == 0
    assert len(d["vertices"]) > len(g["vertices"])
    assert np.array_equal(d["vertices"][:8], g["vertices"])
    assert mesh_area(d) == pytest.approx(polygon_area(g["vertices"]), abs=1e-12)


def on_wall(p):
    """p on a wall of the notch, not at its top (y = 1) or bottom (y = 0)."""
    return (p[..., 0] > 0.94) & (p[..., 0] < 1.06) & (p[..., 1] > 0) & (p[..., 1] < 1)


def test_split_walls_keep_their_markers():
    d = pdd.triangulate(notch(), "pD")
    v, s, m = d["vertices"], d["segments"], d["segment_markers"][:, 0]
    a, b = v[s[:, 0]], v[s[:, 1]]
    near = lambda p: (p[:, 0] > 0.94) & (p[:, 0] < 1.06)
    wall = (on_wall(a) | on_wall(b)) & near(a) & near(b)
    assert np.array_equal(m, np.where(wall, 5, 1))
    assert np.count_nonzero(m == 5) > 3
    assert np.array_equal(d["vertex_markers"][8:, 0], np.where(on_wall(v[8:]), 5, 1))


@pytest.mark.parametrize("opts", ["pq30a0.002D", "pq25D"])
def test_quality_bounds_and_delaunay_with_D(opts):
    r = pdd.triangulate(holed_square(), opts)
    assert delaunay_violations(r) == 0
    assert mesh_area(r) == pytest.approx(0.96, abs=1e-12)
    v, t = r["vertices"], r["triangles"]
    e = [np.linalg.norm(v[t[:, (i + 1) % 3]] - v[t[:, (i + 2) % 3]], axis=1) for i in range(3)]
    cos = [(e[(i + 1) % 3] ** 2 + e[(i + 2) % 3] ** 2 - e[i] ** 2) / (2 * e[(i + 1) % 3] * e[(i + 2) % 3])
           for i in range(3)]
    min_angle = np.degrees(np.arccos(np.clip(np.max(cos, axis=0), -1, 1))).min()
    assert min_angle >= (30 if "q30" in opts else 25) - 1e-9
    if "a0.002" in opts:
        va, vb, vc = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
        area = 0.5 * ((vb[:, 0] - va[:, 0]) * (vc[:, 1] - va[:, 1]) - (vb[:, 1] - va[:, 1]) * (vc[:, 0] - va[:, 0]))
        assert area.max() <= 0.002


def test_steiner_budget_caps_the_count():
    g = holed_square()
    n = len(g["vertices"])
    assert len(pdd.triangulate(g, "pq30a0.001")["vertices"]) > n + 40
    for opts in ("pq30a0.001S40", "pq30a0.001DS40"):
        r = pdd.triangulate(g, opts)
        assert len(r["vertices"]) == n + 40, opts
        assert mesh_area(r) == pytest.approx(0.96, abs=1e-12)
    none = pdd.triangulate(g, "pq30S0")
    assert np.array_equal(none["vertices"], g["vertices"])
    ample = pdd.triangulate(g, "pqS100000")
    assert n < len(ample["vertices"]) < n + 100000
