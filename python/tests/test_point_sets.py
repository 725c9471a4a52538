"""pytest tests of Triangle without p (vertex sets), of c, e and v, and of the triangle package's
delaunay, convex_hull and voronoi: shapes and dtypes as the package returns them, and the
properties a user checks (empty circumcircles tested exactly on integer points, the hull's
area, every vertex kept, Voronoi vertices equidistant from their sites, rays outward)."""
import math
import warnings
from fractions import Fraction

import numpy as np
import pytest

import pdd

DOC_POINTS = [[0, 0], [0, 1], [0.5, 0.5], [1, 1], [1, 0]]  # the triangle package's examples


def r2_points(n):
    """The R2 sequence in the unit square, as tests/triangle/point_sets_test.cpp makes it."""
    return np.array([[math.fmod(i * 0.6180339887498949, 1.0),
                      math.fmod(i * 0.7548776662466927, 1.0)] for i in range(n)])


def tri_set(t):
    return {frozenset(map(int, row)) for row in t}


def edge_count(t):
    """Undirected edge -> number of triangles that have it."""
    use = {}
    for row in t.tolist():
        for i in range(3):
            k = tuple(sorted((row[i], row[(i + 1) % 3])))
            use[k] = use.get(k, 0) + 1
    return use


def hull_area_exact(points):
    """Twice the convex hull's area of integer points, exactly (monotone chain, Python ints)."""
    pts = sorted(set(map(tuple, points)))

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    hull = lower[:-1] + upper[:-1]
    return sum(hull[i][0] * hull[i - 1][1] - hull[i - 1][0] * hull[i][1] for i in range(len(hull))) * -1


def test_the_triangle_package_examples():
    t = pdd.delaunay(DOC_POINTS)
    assert t.dtype == np.int32 and t.shape == (4, 3)
    assert tri_set(t) == tri_set([[1, 0, 2], [2, 4, 3], [4, 2, 0], [2, 3, 1]])  # triangle's doc
    h = pdd.convex_hull([[0, 0], [0, 1], [1, 1], [1, 0]])
    assert h.dtype == np.int32 and h.shape == (4, 2)
    assert {frozenset(e) for e in h.tolist()} == {frozenset(e) for e in [[3, 0], [2, 3], [1, 2], [0, 1]]}
    p, e, o, d = pdd.voronoi(DOC_POINTS)
    assert p.dtype == np.float64 and p.shape == (4, 2)
    assert e.dtype == np.int32 and e.shape == (4, 2)
    assert o.dtype == np.int32 and o.shape == (4,)
    assert d.dtype == np.float64 and d.shape == (4, 2)
    assert sorted(map(tuple, p.tolist())) == [(0.0, 0.5), (0.5, 0.0), (0.5, 1.0), (1.0, 0.5)]
    rays = {(tuple(p[i]), tuple(dd)) for i, dd in zip(o.tolist(), d.tolist())}
    assert rays == {((0.0, 0.5), (-1.0, 0.0)), ((1.0, 0.5), (1.0, 0.0)),
                    ((0.5, 0.0), (0.0, -1.0)), ((0.5, 1.0), (0.0, 1.0))}
    # triangulate({'vertices': v}, 'a0.2'): Triangle's doc gives 9 vertices, 8 triangles
    out = pdd.triangulate({"vertices": [[0, 0], [0, 1], [1, 1], [1, 0]]}, "a0.2")
    assert out["vertices"].shape == (9, 2) and out["triangles"].shape == (8, 3)
    assert out["vertex_markers"].shape == (9, 1) and out["vertex_markers"][:4].ravel().tolist() == [1] * 4
    assert set(out) == {"vertices", "vertex_markers", "triangles"}


def test_delaunay_of_integer_points_is_exactly_delaunay():
    rng = np.random.default_rng(35)
    pts = rng.integers(0, 60, size=(400, 2))  # duplicates and cocircular quadruples
    distinct = {}
    first = [distinct.setdefault(tuple(q), i) for i, q in enumerate(pts.tolist())]
    dups = sum(1 for i, f in enumerate(first) if f != i)
    with pytest.warns(UserWarning, match=f"duplicates vertex .*and {dups - 1} more") as caught:
        t = pdd.delaunay(pts.astype(float))
    assert len(caught) == 1  # one warning, not one per duplicate
    used = set(t.ravel().tolist())
    assert used == {i for i, f in enumerate(first) if f == i}  # every distinct point, no duplicate
    a, b, c = pts[t[:, 0]], pts[t[:, 1]], pts[t[:, 2]]
    twice = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    assert (twice > 0).all()  # counter-clockwise
    assert int(twice.sum()) == hull_area_exact(pts.tolist())  # exactly the hull
    # no point strictly inside any circumcircle: the in-circle determinant in integers (exact)
    for tri in t:
        d = pts[tri][None, :, :] - pts[:, None, :]  # (n, 3, 2)
        lift = (d ** 2).sum(2)
        det = (d[:, 0, 0] * (d[:, 1, 1] * lift[:, 2] - lift[:, 1] * d[:, 2, 1])
               - d[:, 0, 1] * (d[:, 1, 0] * lift[:, 2] - lift[:, 1] * d[:, 2, 0])
               + lift[:, 0] * (d[:, 1, 0] * d[:, 2, 1] - d[:, 1, 1] * d[:, 2, 0]))
        assert (det <= 0).all()


@pytest.mark.parametrize("opts, triangle_count", [("q", 1161), ("qa0.002", 1241), ("q30a0.001", 1912)])
def test_quality_mesh_of_a_point_set(opts, triangle_count):
    pts = r2_points(500)
    out = pdd.triangulate({"vertices": pts}, opts)
    v, t = out["vertices"], out["triangles"]
    assert np.array_equal(v[:500], pts)  # every input vertex kept first, in order
    assert set(range(500)) <= set(t.ravel().tolist())
    assert len(v) > 500  # refinement added vertices
    # within 8 % of Triangle 1.6's count on the same vertices (1-5 % over, with off-centres)
    assert abs(len(t) - triangle_count) < 0.08 * triangle_count
    # pdd's verifier on the hull's PSLG: Delaunay, the hull covered, angle and area bounds
    hull = pdd.convex_hull(pts)
    angle = 30.0 if opts.startswith("q30") else 20.0
    area = float(opts.split("a")[1]) if "a" in opts else None
    r = pdd.verify(dict(vertices=pts, segments=hull), out, min_angle=angle, max_area=area)
    assert r["ok"], r["messages"]


def test_edges_with_triangle_markers():
    sq = dict(vertices=np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.5]], dtype=float),
              segments=np.array([[0, 1], [1, 2], [2, 3], [3, 0]]), segment_markers=np.array([5, 5, 5, 5]))
    for tri, opts in ((sq, "pqa0.01e"), ({"vertices": r2_points(300)}, "e")):
        out = pdd.triangulate(tri, opts)
        e, m = out["edges"], out["edge_markers"]
        assert e.dtype == np.int32 and m.dtype == np.int32 and m.shape == (len(e), 1)
        use = edge_count(out["triangles"])
        keys = [tuple(sorted(x)) for x in e.tolist()]
        assert len(keys) == len(set(keys)) == len(use)  # each edge of the triangles once
        on_boundary = 5 if "segments" in tri else 1
        assert [k[0] for k in m.tolist()] == [on_boundary if use[k] == 1 else 0 for k in keys]
    assert "edge_markers" not in pdd.triangulate(sq, "peB") and "edges" in pdd.triangulate(sq, "peB")


def test_voronoi_is_dual_to_the_delaunay_triangulation():
    pts = r2_points(300)
    out = pdd.triangulate({"vertices": pts}, "vn")
    t, nb, vor = out["triangles"], out["neighbors"], out["voronoi"]
    p, e, o, d = pdd.voronoi(pts)
    for a, b in zip((p, e, o, d), (vor["vertices"], vor["edges"], vor["ray_origins"], vor["ray_directions"])):
        assert np.array_equal(a, b)
    assert len(p) == len(t)
    r = [np.linalg.norm(p - pts[t[:, k]], axis=1) for k in range(3)]
    assert np.allclose(r[0], r[1], rtol=1e-9, atol=0) and np.allclose(r[0], r[2], rtol=1e-9, atol=0)
    use = edge_count(t)
    assert len(e) + len(o) == len(use) and len(o) == sum(1 for n in use.values() if n == 1)
    for a, b in e.tolist():  # a finite edge joins two triangles that share an edge
        assert len(set(t[a].tolist()) & set(t[b].tolist())) == 2
    for origin, direction in zip(o.tolist(), d):
        ok = False
        for k in range(3):  # one of the origin's boundary edges, rotated clockwise: outward
            if nb[origin][k] != -1:
                continue
            a, b = pts[t[origin][(k + 1) % 3]], pts[t[origin][(k + 2) % 3]]
            edge = b - a
            # exactly, in rationals: numpy's dot may use a BLAS with fused multiply-adds, which
            # leaves the rounding error of one product where ey * ex - ex * ey is 0
            dx, dy, ex, ey = (Fraction(float(c)) for c in (*direction, *edge))
            ok |= dx * ex + dy * ey == 0 and ex * dy - ey * dx < 0
        assert ok


def test_convex_hull_of_a_pslg_and_unread_keys():
    ell = dict(vertices=np.array([[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]], dtype=float),
               segments=np.array([[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0]]))
    plain, hull = pdd.triangulate(ell, "pqa0.05"), pdd.triangulate(ell, "pcqa0.05")

    def area(out):
        v, t = out["vertices"], out["triangles"]
        a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
        return (0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))).sum()

    assert area(plain) == pytest.approx(3.0, rel=1e-12) and area(hull) == pytest.approx(3.5, rel=1e-12)
    assert 1 in hull["segment_markers"].ravel().tolist()  # the new hull segment
    # without p the segments are not read (Triangle's rule), and pdd says so
    with pytest.warns(UserWarning, match="'segments' are not read without switch p"):
        out = pdd.triangulate(ell, "")
    assert tri_set(out["triangles"]) == tri_set(pdd.delaunay(ell["vertices"]))
    assert "segments" not in out
    with pytest.warns(UserWarning):
        assert len(pdd.triangulate(ell, "c")["segments"]) == 5  # the hull (2,1)-(1,2) cuts the notch
    # a quality mesh of a vertex set with c: the hull's pieces as segments, marker 1
    out = pdd.triangulate({"vertices": ell["vertices"]}, "cqa0.05")
    assert (out["segment_markers"] == 1).all() and len(out["segments"]) > 5
    use = edge_count(out["triangles"])
    assert {tuple(sorted(s)) for s in out["segments"].tolist()} == {k for k, n in use.items() if n == 1}


@pytest.mark.parametrize("points, message", [
    ([[0, 0], [1, 1]], "at least three distinct"),
    ([[0, 0], [1, 1], [1, 1]], "at least three distinct"),
    ([[0, 0], [1, 1], [2, 2], [3, 3]], "collinear"),
    ([[0, 0], [1, float("inf")], [2, 3]], "not finite"),
    (np.zeros((3, 3)), "shape"),
    ([], "at least three distinct"),
])
def test_bad_point_sets_raise_value_error(points, message):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for call in (pdd.delaunay, pdd.convex_hull, pdd.voronoi,
                     lambda p: pdd.triangulate({"vertices": p}, "q")):
            with pytest.raises(ValueError, match=message):
                call(points)
