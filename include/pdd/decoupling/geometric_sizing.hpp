/// \file geometric_sizing.hpp
/// pdd::geometric_sizing: the sizing function built from the geometry on a decomposition
/// (dissertation 8.2, Algorithm 8.3): F <= f with m_F(D_i) <= 4 sqrt2 e_i^2 (e_i from
/// lfs_min(D_i), m_f(D_i) and the small angles of D_i) and m_F(D_i) <= R2 m_F(D_j) across
/// every separator, so that the graded decoupling path (Theorem 22) exists for F.
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/core/bbox.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/decoupling/decouple.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/madd/gradation_control.hpp>
#include <pdd/parallel/sequential_executor.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/domain_region.hpp>
#include <pdd/sizing/geometric_bound.hpp>
#include <pdd/sizing/inverse_area_integral.hpp>
#include <pdd/sizing/mesh_size_estimate.hpp>
#include <pdd/sizing/piecewise_scaled.hpp>
#include <pdd/sizing/sizing_range.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// Algorithm 8.3's numbers per subdomain and the field F it builds.
struct geometric_sizing_result {
  std::optional<piecewise_scaled_sizing> field; ///< F (always set by pdd::geometric_sizing)
  std::vector<double> area_min;   ///< m_f(D_i): lower bound of min(max_area, f) over D_i
  std::vector<double> area_max;   ///< M_f(D_i)
  std::vector<double> lfs;        ///< lfs_min(D_i) (pdd::decouple's per-subdomain value)
  std::vector<double> edge_bound; ///< e_i (relations 8.9-8.11)
  std::vector<double> local_g;    ///< g_i = 4 sqrt2 e_i^2 (8.13), before the R2 propagation
  std::vector<double> g;          ///< after it: m_F(D_i)
  /// Expected triangles of D_i under min(max_area, f): integral of 1 / (0.656 f).
  std::vector<double> expected_f;
  std::size_t lowered = 0; ///< subdomains whose g the R2 propagation lowered
  /// The scale g_i / m_f(D_i) of subdomain i (F = f * scale there).
  double scale(std::size_t i) const { return g[i] / area_min[i]; }
  /// Expected triangles under f and under F (the integral of 1 / (0.656 F) = sum of
  /// expected_f_i / scale_i).
  double expected_triangles_f() const {
    double s = 0.0;
    for (const double e : expected_f)
      s += e;
    return s;
  }
  /// Expected triangles under F: the sum of expected_f[i] / scale(i), the integral of
  /// 1 / (0.656 F).
  double expected_triangles_F() const {
    double s = 0.0;
    for (std::size_t i = 0; i < g.size(); ++i)
      s += expected_f[i] / scale(i);
    return s;
  }
  /// Estimated over-refinement of F against f: expected_triangles_F / expected_triangles_f - 1.
  double over_refinement() const {
    const double ef = expected_triangles_f();
    return ef > 0.0 ? expected_triangles_F() / ef - 1.0 : 0.0;
  }
};

namespace detail {
/// The angles (radians) of subdomain s at its loop corners, measured inside the subdomain
/// (outer loop counter-clockwise, holes clockwise: the subdomain lies to the left).
inline std::vector<double> subdomain_corner_angles(const decomposition& d, std::size_t s) {
  std::vector<double> out;
  for (const auto& loop : d.subdomains[s].loops)
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const point a = d.vertices[loop[(i + loop.size() - 1) % loop.size()]];
      const point b = d.vertices[loop[i]], c = d.vertices[loop[(i + 1) % loop.size()]];
      const double ux = c.x - b.x, uy = c.y - b.y, vx = a.x - b.x, vy = a.y - b.y;
      double angle = std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
      if (angle < 0.0) angle += 2.0 * std::numbers::pi;
      out.push_back(angle);
    }
  return out;
}

/// Per subdomain: the triangles of its constrained Delaunay triangulation (points), its
/// bounds of min(max_area, f) and its expected triangles under f.
struct geometric_piece {
  std::vector<point> vertices;
  std::vector<std::array<index_t, 3>> triangles;
  sizing_bounds bounds;
  double expected = 0.0;
};

inline geometric_piece measure_geometric_piece(const decomposition& d, std::size_t s,
                                               const any_sizing& f, double max_area) {
  geometric_piece p;
  pslg g;
  for (const auto& loop : subdomain_points(d, s))
    g.add_loop(loop);
  const std::vector<domain_triangle> triangles = domain_faces(g).triangles();
  const sizing_bounds r = f ? sizing_range(f, domain_region(g.vertices, triangles).view())
                            : sizing_bounds{max_area, max_area};
  p.bounds = {std::min(max_area, r.lo), std::min(max_area, r.hi)};
  for (const domain_triangle& t : triangles)
    p.triangles.push_back(t.vertices);
  p.expected = inverse_area_integral(g.vertices, triangles, max_area, f, f ? 1024 : 1) /
               mean_triangle_area_fraction;
  p.vertices = std::move(g.vertices);
  return p;
}
} // namespace detail

/// Algorithm 8.3 on the decomposition d for the user's field min(max_area, f) (f may be empty:
/// the uniform bound max_area alone):
///  1. per subdomain, m_f(D_i) (pdd::sizing_range over its bounding box: a true lower bound),
///     lfs_min(D_i) (the value pdd::decouple uses), its corner angles below 60 deg, and
///     e_i (pdd::geometric_edge_bound, relations 8.9-8.11), g_i = 4 sqrt2 e_i^2 (8.13);
///  2. the R2 bound g_j <= R2 g_i across every interface of d (pdd::propagate_gradation: a
///     heap instead of the text's O(N^2) list);
///  3. F|D_i = f|D_i g_i / m_f(D_i) (8.14, step 12): a pdd::piecewise_scaled_sizing located
///     on the subdomains' constrained triangulations, with m_F(D_i) = g_i and M_F(D_i) =
///     M_f(D_i) g_i / m_f(D_i) exact.
/// F <= f (8.17), m_F(D_i) <= g_i (condition (ii)), M_F <= R1 m_F wherever f meets Condition
/// 1 on D_i (8.16), and m_F(D_i) <= R2 m_F(D_j) for neighbours (Proposition 25).
/// \throws pdd::sizing_error when min(max_area, f) has no finite lower bound on a subdomain
/// (Algorithm 8.3 scales a bounded f), or R2 <= 1; pdd::geometry_error / decoupling_error as
/// pdd::decouple for a malformed decomposition.
/// Complexity: per subdomain one sizing_range, two constrained triangulations (lfs and the
/// pieces) and 1024 evaluations of f; then O((N + P) log N). Deterministic for every
/// executor.
template <Executor E = sequential_executor>
geometric_sizing_result geometric_sizing(const decomposition& d, const any_sizing& f,
                                         double max_area, double r2, const E& executor = {}) {
  detail::check_decomposition(d);
  const std::size_t m = d.subdomains.size();
  geometric_sizing_result out;
  out.lfs = detail::subdomain_lfs(d, executor);
  std::vector<detail::geometric_piece> pieces(m);
  std::vector<double> work(m, 1.0);
  executor.run(work,
               [&](index_t s) { pieces[s] = detail::measure_geometric_piece(d, s, f, max_area); });
  for (std::size_t s = 0; s < m; ++s) {
    const double lo = pieces[s].bounds.lo;
    if (!(lo > 0.0) || !std::isfinite(lo))
      throw sizing_error("geometric_sizing: the area bound of subdomain " + std::to_string(s) +
                         " has no finite positive lower bound (m_f = " + std::to_string(lo) +
                         "); Algorithm 8.3 needs an area bound (max_area or a bounded field)");
    out.area_min.push_back(lo);
    out.area_max.push_back(pieces[s].bounds.hi);
    out.expected_f.push_back(pieces[s].expected);
    const std::vector<double> angles = detail::subdomain_corner_angles(d, s);
    out.edge_bound.push_back(geometric_edge_bound(lo, out.lfs[s], angles));
    // 8.17: g_i <= m_f(D_i) (e_i <= m_i <= (1/2) sqrt(m_f / sqrt2)); min() keeps rounding out
    out.local_g.push_back(std::min(lo, geometric_area_bound(out.edge_bound.back())));
  }
  out.g = out.local_g;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const interface_curve& c : d.interfaces)
    pairs.emplace_back(c.a, c.b);
  out.lowered = propagate_gradation(out.g, pairs, r2);
  std::vector<point> vertices;
  std::vector<std::array<index_t, 3>> triangles;
  std::vector<index_t> piece_of;
  std::vector<double> scale;
  std::vector<sizing_bounds> bounds;
  for (std::size_t s = 0; s < m; ++s) {
    const auto base = static_cast<index_t>(vertices.size());
    vertices.insert(vertices.end(), pieces[s].vertices.begin(), pieces[s].vertices.end());
    for (const auto& t : pieces[s].triangles) {
      triangles.push_back({base + t[0], base + t[1], base + t[2]});
      piece_of.push_back(static_cast<index_t>(s));
    }
    scale.push_back(out.scale(s));
    bounds.push_back({out.g[s], out.area_max[s] * out.scale(s)});
  }
  out.field.emplace(f, max_area, std::move(vertices), std::move(triangles), piece_of,
                    std::move(scale), std::move(bounds));
  return out;
}

} // namespace pdd
