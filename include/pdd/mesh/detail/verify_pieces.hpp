/// \file verify_pieces.hpp
/// Implementation of pdd::verify_pieces: the table of open piece-boundary edges keyed by their
/// endpoints' exact bits, and the index of the input segments that the unmatched boundary edges
/// must lie on.
#pragma once

#include <pdd/core/bbox.hpp>
#include <pdd/core/kernel.hpp>
#include <pdd/core/point.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/mesh/detail/verify.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace pdd::detail::pieces_impl {

/// An undirected edge by its endpoints' bit patterns, the smaller (as bits) first: two edges
/// are the same key only if their endpoints are bitwise equal.
struct edge_key {
  std::array<std::uint64_t, 4> bits{};
  bool operator==(const edge_key&) const = default;
};

struct edge_key_hash {
  std::size_t operator()(const edge_key& k) const noexcept {
    std::uint64_t h = 0x9E3779B97F4A7C15ULL;
    for (const std::uint64_t b : k.bits)
      h = (h ^ b) * 0x100000001B3ULL + (h >> 29);
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
};

inline std::array<std::uint64_t, 2> point_bits(const point& p) {
  return {std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(p.y)};
}

/// The key of edge (p, q) and whether p is its first endpoint.
inline std::pair<edge_key, bool> make_key(const point& p, const point& q) {
  const auto bp = point_bits(p), bq = point_bits(q);
  const bool p_first = bp < bq;
  const auto& f = p_first ? bp : bq;
  const auto& s = p_first ? bq : bp;
  return {edge_key{{f[0], f[1], s[0], s[1]}}, p_first};
}

/// One side of a piece-boundary edge still waiting for its other side: the piece, the
/// triangle (index in its piece), the directed endpoints as that triangle runs them, and the
/// triangle's third vertex.
struct open_edge {
  std::uint32_t piece = 0;
  index_t triangle = 0;
  point from, to, apex;
};

using open_edge_table = std::unordered_map<edge_key, open_edge, edge_key_hash>;

/// True if `s1` lies strictly inside the circle through the triangle (p, q, s0) (exact
/// side_of_oriented_circle; a degenerate (p, q, s0) is never a violation here: it is reported
/// as a degenerate triangle by its piece).
inline bool strictly_in_circle(const point& p, const point& q, const point& s0, const point& s1) {
  using verify_impl::to_cgal;
  const auto a = to_cgal(p), b = to_cgal(q), c = to_cgal(s0), d = to_cgal(s1);
  const CGAL::Orientation o = CGAL::orientation(a, b, c);
  if (o == CGAL::COLLINEAR) return false;
  const auto side = o == CGAL::LEFT_TURN ? CGAL::side_of_oriented_circle(a, b, c, d)
                                         : CGAL::side_of_oriented_circle(b, a, c, d);
  return side == CGAL::ON_POSITIVE_SIDE;
}

/// The input segments in a uniform grid of about one cell per segment: a query edge is tested
/// against the segments of the cell of its first endpoint only (each segment is entered in
/// every cell its box, widened by 1e-9 of the domain's size, overlaps).
class segment_index {
public:
  explicit segment_index(const pslg& g) : g_(g) {
    for (const segment& s : g.segments)
      for (const index_t v : {s.a, s.b}) {
        box_.xmin = std::min(box_.xmin, g.vertices[v].x);
        box_.xmax = std::max(box_.xmax, g.vertices[v].x);
        box_.ymin = std::min(box_.ymin, g.vertices[v].y);
        box_.ymax = std::max(box_.ymax, g.vertices[v].y);
      }
    side_ = std::clamp<std::size_t>(
        static_cast<std::size_t>(std::sqrt(static_cast<double>(g.segments.size()))), 1, 1024);
    if (box_.empty()) return;
    margin_ = 1e-9 * std::max(box_.width(), box_.height());
    cells_.assign(side_ * side_, {});
    for (std::size_t k = 0; k < g.segments.size(); ++k) {
      const point& a = g.vertices[g.segments[k].a];
      const point& b = g.vertices[g.segments[k].b];
      const std::size_t x0 = cell_x(std::min(a.x, b.x) - margin_);
      const std::size_t x1 = cell_x(std::max(a.x, b.x) + margin_);
      const std::size_t y0 = cell_y(std::min(a.y, b.y) - margin_);
      const std::size_t y1 = cell_y(std::max(a.y, b.y) + margin_);
      for (std::size_t y = y0; y <= y1; ++y)
        for (std::size_t x = x0; x <= x1; ++x)
          cells_[y * side_ + x].push_back(static_cast<index_t>(k));
    }
  }

  /// True if both p and q lie on one input segment (verify_impl::on_segment_line, and
  /// between its endpoints).
  bool on_a_segment(const point& p, const point& q) const {
    if (box_.empty() || p.x < box_.xmin - margin_ || p.x > box_.xmax + margin_ ||
        p.y < box_.ymin - margin_ || p.y > box_.ymax + margin_)
      return false;
    for (const index_t k : cells_[cell_y(p.y) * side_ + cell_x(p.x)]) {
      const point& a = g_.vertices[g_.segments[k].a];
      const point& b = g_.vertices[g_.segments[k].b];
      if (within(a, b, p) && within(a, b, q)) return true;
    }
    return false;
  }

private:
  static bool within(const point& a, const point& b, const point& q) {
    if (!verify_impl::on_segment_line(a, b, q)) return false;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double t = ((q.x - a.x) * dx + (q.y - a.y) * dy) / (dx * dx + dy * dy);
    return t >= 0.0 && t <= 1.0;
  }
  std::size_t cell(double v, double lo, double extent) const {
    if (!(extent > 0.0)) return 0;
    const double c = (v - lo) / extent * static_cast<double>(side_);
    return static_cast<std::size_t>(std::clamp(c, 0.0, static_cast<double>(side_ - 1)));
  }
  std::size_t cell_x(double x) const { return cell(x, box_.xmin, box_.width()); }
  std::size_t cell_y(double y) const { return cell(y, box_.ymin, box_.height()); }

  const pslg& g_;
  pdd::bbox box_;
  std::size_t side_ = 1;
  double margin_ = 0.0;
  std::vector<std::vector<index_t>> cells_;
};

} // namespace pdd::detail::pieces_impl
