// Tests of pdd::constrained_delaunay_2: exact properties (the constrained Delaunay property,
// adjacency, the convex hull, constraints as edges) on many seeded random inputs, integer grids
// (cocircular and collinear points) and one-by-one or batch insertion; and, outside the
// permissive build, the same triangles and constrained edges as CGAL's
// Constrained_Delaunay_triangulation_2 (cocircular points too: both perturb ties alike).
#include <pdd/triangulation/constrained_delaunay_2.hpp>

#ifndef PDD_PERMISSIVE
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#endif

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace constrained_delaunay_2_test {

using P = pdd::epick::Point_2;
using cdt = pdd::constrained_delaunay_2<int, int>;

struct input {
  std::vector<std::pair<P, int>> points;
  std::vector<std::pair<int, int>> segments; ///< no two cross, none through a vertex
};

bool blocked(const input& in, const P& a, const P& b) {
  for (const auto& [x, y] : in.segments) {
    const P &px = in.points[x].first, &py = in.points[y].first;
    const bool shared = px == a || px == b || py == a || py == b;
    if (shared ? CGAL::collinear(a, b, px) && CGAL::collinear(a, b, py)
               : CGAL::do_intersect(pdd::epick::Segment_2(a, b), pdd::epick::Segment_2(px, py)))
      return true;
  }
  for (const auto& [q, id] : in.points)
    if (q != a && q != b && CGAL::collinear(a, b, q) &&
        CGAL::collinear_are_ordered_along_line(a, q, b))
      return true;
  return false;
}

/// n points (random, or on a 12 x 12 grid: duplicates, cocircular and collinear points) and
/// up to n random segments that neither cross nor pass through a vertex.
input random_input(unsigned seed, int n, bool grid) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  input in;
  for (int i = 0; i < n; ++i)
    in.points.emplace_back(grid ? P(rng() % 12, rng() % 12) : P(u(rng), u(rng)), i);
  for (int k = 0; k < n; ++k) {
    const int a = static_cast<int>(rng() % n), b = static_cast<int>(rng() % n);
    const P &pa = in.points[a].first, &pb = in.points[b].first;
    if (pa != pb && !blocked(in, pa, pb)) in.segments.emplace_back(a, b);
  }
  return in;
}

/// Builds the triangulation (batch or one by one); handle[i] is input point i's vertex.
std::vector<cdt::Vertex_handle> build(const input& in, cdt& t, bool batch) {
  if (batch) t.insert(in.points.begin(), in.points.end());
  std::vector<cdt::Vertex_handle> handle;
  for (const auto& [p, id] : in.points) {
    const std::size_t before = t.number_of_vertices();
    handle.push_back(t.insert(p));
    if (t.number_of_vertices() != before) handle.back()->info() = id;
  }
  for (const auto& [a, b] : in.segments)
    t.insert_constraint(handle[a], handle[b]);
  return handle;
}

/// Adjacency, orientation and the constrained Delaunay property, checked exactly.
void expect_valid(const cdt& t) {
  for (const auto f : t.all_face_handles())
    for (int i = 0; i < 3; ++i) {
      const auto n = f->neighbor(i);
      const int j = n->index(f);
      ASSERT_EQ(n->neighbor(j), f);
      ASSERT_EQ(n->is_constrained(j), f->is_constrained(i));
      ASSERT_EQ(f->vertex(cdt::ccw(i)), n->vertex(cdt::cw(j)));
    }
  for (const auto f : t.finite_face_handles()) {
    const P &a = f->vertex(0)->point(), &b = f->vertex(1)->point(), &c = f->vertex(2)->point();
    ASSERT_EQ(CGAL::orientation(a, b, c), CGAL::LEFT_TURN);
    for (int i = 0; i < 3; ++i) {
      const auto n = f->neighbor(i);
      if (f->is_constrained(i) || t.is_infinite(n)) continue;
      ASSERT_NE(CGAL::side_of_oriented_circle(a, b, c, n->vertex(n->index(f))->point()),
                CGAL::ON_POSITIVE_SIDE);
    }
  }
}

/// Faces = 2n - h - 2 for n vertices, h of them on the hull; every hull corner is convex.
void expect_hull(const cdt& t) {
  std::size_t h = 0;
  for (const auto f : t.all_face_handles()) {
    if (!t.is_infinite(f)) continue;
    ++h;
    const int i = f->index(t.infinite_vertex());
    const auto a = f->vertex(cdt::ccw(i)), b = f->vertex(cdt::cw(i));
    for (const auto v : t.finite_vertex_handles()) // nothing outside the hull edge a -> b
      ASSERT_NE(CGAL::orientation(a->point(), b->point(), v->point()), CGAL::LEFT_TURN);
  }
  EXPECT_EQ(t.number_of_faces(), 2 * t.number_of_vertices() - h - 2);
}

TEST(ConstrainedDelaunay2, RandomAndGridInputsAreConstrainedDelaunayWithTheirSegments) {
  for (unsigned seed = 0; seed < 120; ++seed) {
    SCOPED_TRACE(seed);
    const input in = random_input(seed, 4 + static_cast<int>(seed % 150), seed % 3 == 0);
    cdt t;
    const auto handle = build(in, t, seed % 2 == 1);
    if (t.dimension() < 2) continue;
    expect_valid(t);
    expect_hull(t);
    for (const auto& [a, b] : in.segments) {
      cdt::Face_handle f;
      int i = 0;
      ASSERT_TRUE(t.is_edge(handle[a], handle[b], f, i));
      EXPECT_TRUE(f->is_constrained(i));
    }
    std::size_t degree_sum = 0;
    for (const auto v : t.finite_vertex_handles()) {
      auto fc = t.incident_faces(v), done = fc;
      do {
        ASSERT_TRUE(fc->has_vertex(v));
        ++degree_sum;
      } while (++fc != done);
    }
    std::size_t infinite = 0;
    for (const auto f : t.all_face_handles())
      infinite += t.is_infinite(f) ? 1 : 0;
    EXPECT_EQ(degree_sum, 3 * t.number_of_faces() + 2 * infinite); // 2 finite corners each
  }
}

TEST(ConstrainedDelaunay2, LocateFindsTheFaceHoldingThePoint) {
  const input in = random_input(7, 300, false);
  cdt t;
  build(in, t, true);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.3, 1.3);
  for (int k = 0; k < 2000; ++k) {
    const P q(u(rng), u(rng));
    cdt::Locate_type lt{};
    int li = 0;
    const auto f = t.locate(q, lt, li);
    if (lt == cdt::OUTSIDE_CONVEX_HULL) {
      const int i = f->index(t.infinite_vertex());
      EXPECT_EQ(
          CGAL::orientation(f->vertex(cdt::ccw(i))->point(), f->vertex(cdt::cw(i))->point(), q),
          CGAL::LEFT_TURN);
      continue;
    }
    ASSERT_EQ(lt, cdt::FACE); // random doubles: never on an edge
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(
          CGAL::orientation(f->vertex(cdt::ccw(i))->point(), f->vertex(cdt::cw(i))->point(), q),
          CGAL::LEFT_TURN);
  }
  const auto v = t.finite_vertices_begin();
  cdt::Locate_type lt{};
  int li = 0;
  const auto f = t.locate(v->point(), lt, li);
  EXPECT_EQ(lt, cdt::VERTEX);
  EXPECT_EQ(f->vertex(li), *v);
}

TEST(ConstrainedDelaunay2, CollinearPointsWaitForATriangle) {
  cdt t;
  EXPECT_EQ(t.dimension(), -1);
  const auto a = t.insert(P(0, 0));
  EXPECT_EQ(t.dimension(), 0);
  const auto b = t.insert(P(2, 0));
  const auto c = t.insert(P(1, 0));
  t.insert_constraint(a, c);
  EXPECT_EQ(t.insert(P(1, 0)), c); // the same point: the same vertex
  EXPECT_EQ(t.dimension(), 1);
  EXPECT_EQ(t.number_of_faces(), 0u);
  const auto d = t.insert(P(1, 1));
  EXPECT_EQ(t.dimension(), 2);
  EXPECT_EQ(t.number_of_vertices(), 4u);
  EXPECT_EQ(t.number_of_faces(), 2u);
  cdt::Face_handle f;
  int i = 0;
  ASSERT_TRUE(t.is_edge(a, c, f, i));
  EXPECT_TRUE(f->is_constrained(i)); // the constraint inserted before the triangle
  EXPECT_FALSE(t.is_edge(a, b));
  EXPECT_TRUE(t.is_edge(c, d));
  expect_valid(t);
  expect_hull(t);
}

TEST(ConstrainedDelaunay2, AVertexOnAConstraintSplitsItOrIsRefused) {
  for (const bool split : {true, false}) {
    cdt t(split ? pdd::constraint_crossing::split_at_vertices : pdd::constraint_crossing::refuse);
    const auto a = t.insert(P(0, 0)), b = t.insert(P(4, 0)), m = t.insert(P(2, 0));
    t.insert(P(2, 3));
    t.insert(P(2, -3));
    if (!split) {
      EXPECT_THROW(t.insert_constraint(a, b), cdt::Intersection_of_constraints_exception);
      continue;
    }
    t.insert_constraint(a, b);
    cdt::Face_handle f;
    int i = 0;
    ASSERT_TRUE(t.is_edge(a, m, f, i));
    EXPECT_TRUE(f->is_constrained(i));
    ASSERT_TRUE(t.is_edge(m, b, f, i));
    EXPECT_TRUE(f->is_constrained(i));
  }
}

TEST(ConstrainedDelaunay2, CrossingConstraintsAreRefused) {
  cdt t(pdd::constraint_crossing::split_at_vertices);
  const auto a = t.insert(P(0, 0)), b = t.insert(P(2, 2)), c = t.insert(P(0, 2)),
             d = t.insert(P(2, 0));
  t.insert_constraint(a, b);
  EXPECT_THROW(t.insert_constraint(c, d), cdt::Intersection_of_constraints_exception);
}

TEST(ConstrainedDelaunay2, APointOnAConstrainedEdgeSplitsItAndRemovalRestoresDelaunay) {
  const input in = random_input(3, 200, false);
  cdt t;
  const auto handle = build(in, t, true);
  ASSERT_FALSE(in.segments.empty());
  std::size_t split = 0;
  for (const auto& [a, b] : in.segments) {
    cdt::Face_handle f;
    int i = 0;
    if (!t.is_edge(handle[a], handle[b], f, i)) continue;
    const P m = CGAL::midpoint(handle[a]->point(), handle[b]->point());
    if (!CGAL::collinear(handle[a]->point(), handle[b]->point(), m)) continue; // rounded off
    const auto v = t.insert(m, f);
    cdt::Face_handle g;
    int j = 0;
    ASSERT_TRUE(t.is_edge(handle[a], v, g, j));
    EXPECT_TRUE(g->is_constrained(j));
    ASSERT_TRUE(t.is_edge(v, handle[b], g, j));
    EXPECT_TRUE(g->is_constrained(j));
    ++split;
  }
  EXPECT_GT(split, 0u);
  expect_valid(t);
  for (bool any = true; any;) { // remove every constraint: the Delaunay triangulation
    any = false;
    for (const auto f : t.finite_face_handles())
      for (int i = 0; i < 3 && !any; ++i)
        if (f->is_constrained(i)) {
          t.remove_constrained_edge(f, i);
          any = true;
        }
  }
  expect_valid(t);
}

#ifndef PDD_PERMISSIVE
using cgal_cdt = CGAL::Constrained_Delaunay_triangulation_2<
    pdd::epick,
    CGAL::Triangulation_data_structure_2<
        CGAL::Triangulation_vertex_base_with_info_2<int, pdd::epick>,
        CGAL::Constrained_triangulation_face_base_2<pdd::epick>>,
    CGAL::No_constraint_intersection_tag>;

using xy = std::pair<double, double>;

/// The finite triangles and constrained edges by coordinates (a duplicate point's vertex may
/// carry either input id).
template <class T>
std::pair<std::set<std::array<xy, 3>>, std::set<std::pair<xy, xy>>>
faces_and_constraints(const T& t) {
  std::pair<std::set<std::array<xy, 3>>, std::set<std::pair<xy, xy>>> out;
  for (auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f) {
    const auto at = [&f](int i) {
      return xy(f->vertex(i)->point().x(), f->vertex(i)->point().y());
    };
    std::array<xy, 3> a{at(0), at(1), at(2)};
    std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
    out.first.insert(a);
    for (int i = 0; i < 3; ++i)
      if (f->is_constrained(i)) out.second.insert(std::minmax(at(T::ccw(i)), at(T::cw(i))));
  }
  return out;
}

// Cocircular points included: both break ties by the same symbolic perturbation.
TEST(ConstrainedDelaunay2, SameTrianglesAsCgal) {
  for (unsigned seed = 0; seed < 90; ++seed) {
    SCOPED_TRACE(seed);
    const input in = random_input(1000 + seed, 5 + static_cast<int>(seed * 2), seed % 3 == 0);
    cdt ours;
    build(in, ours, seed % 2 == 0);
    cgal_cdt theirs;
    std::vector<cgal_cdt::Vertex_handle> handle;
    for (const auto& [p, id] : in.points) {
      handle.push_back(theirs.insert(p));
      handle.back()->info() = id;
    }
    for (const auto& [a, b] : in.segments)
      theirs.insert_constraint(handle[a], handle[b]);
    EXPECT_EQ(faces_and_constraints(ours), faces_and_constraints(theirs));
  }
}
#endif

} // namespace constrained_delaunay_2_test
