/// \file cdt_insert.hpp
/// Point location and vertex insertion of pdd::constrained_delaunay_2: a visibility walk, and
/// Bowyer-Watson cavities (Bowyer 1981, Watson 1981) constrained as in the native kernel: the
/// cavity grows across unconstrained edges to every face p conflicts with (cdt_core.hpp), and
/// is shrunk until it is star-shaped from p (a face behind a constrained edge stays: Chew's
/// constrained Delaunay condition). A point on a constrained edge splits it: both halves stay
/// constrained, as CGAL does.
#pragma once

#include <pdd/triangulation/detail/cdt_core.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pdd::detail::cdt {

/// Where a point lies (CGAL's Locate_type, same order).
enum class location { vertex, edge, face, outside_convex_hull, outside_affine_hull };

/// The result of a point location: the face, its type, and the corner (vertex) or edge index.
struct located {
  face_t face = no_face;
  location type = location::outside_affine_hull;
  int index = 0;
};

/// Locates p in the 2D triangulation by a visibility walk from `from`, choosing the first edge
/// to test with a deterministic generator so the walk cannot cycle. Outside the hull: an
/// infinite face whose hull edge sees p.
inline located locate(const storage& s, const epick::Point_2& p, face_t from) {
  face_t f = from < s.size() ? from : 0;
  if (s.is_infinite(f)) f = ref_face(s.adj[f][s.index_of(f, infinite)]);
  std::uint32_t rng = 12345u;
  for (;;) {
    rng = rng * 1664525u + 1013904223u;
    const int k = static_cast<int>((rng >> 16) % 3);
    int o[3] = {1, 1, 1};
    bool moved = false;
    for (int e = 0; e < 3 && !moved; ++e) {
      const int i = (k + e) % 3;
      o[i] = orient(s.at(f, next3(i)), s.at(f, prev3(i)), p);
      if (o[i] < 0) {
        f = ref_face(s.adj[f][i]);
        moved = true;
      }
    }
    if (moved && s.is_infinite(f))
      return {f, location::outside_convex_hull, s.index_of(f, infinite)};
    if (moved) continue;
    const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
    if (zeros == 0) return {f, location::face, 0};
    if (zeros == 1) return {f, location::edge, o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2};
    return {f, location::vertex, o[0] != 0 ? 0 : o[1] != 0 ? 1 : 2};
  }
}

/// The scratch arrays of cavity construction (reused: no allocation per insertion once grown).
class cavity {
public:
  /// Grows the cavity of p from `seeds` (faces p conflicts with or lies in). `crossing` (or
  /// no_ref) is a constrained edge between the two seeds that p splits.
  void grow(storage& s, const epick::Point_2& p, const std::vector<face_t>& seeds, ref_t crossing) {
    clear(s);
    crossing_ = crossing;
    for (const face_t f : seeds)
      add(s, f);
    while (!stack_.empty()) {
      const face_t f = stack_.back();
      stack_.pop_back();
      for (int i = 0; i < 3; ++i) {
        if (s.constrained(f, i)) continue;
        const face_t u = ref_face(s.adj[f][i]);
        if ((s.flags[u] & in_cavity_bit) == 0 && s.in_conflict(u, p)) add(s, u);
      }
    }
  }

  /// Removes faces until every finite boundary edge sees p strictly on the cavity's side.
  /// \returns false when a seed would have to go.
  bool make_star_shaped(storage& s, const epick::Point_2& p, std::size_t seeds) {
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t k = 0; k < members_.size() && !changed; ++k) {
        const face_t f = members_[k];
        for (int i = 0; i < 3 && !changed; ++i) {
          if (!on_boundary(s, f, i) || s.corner[f][next3(i)] == infinite ||
              s.corner[f][prev3(i)] == infinite)
            continue;
          if (orient(s.at(f, next3(i)), s.at(f, prev3(i)), p) > 0) continue;
          if (k < seeds) return false;
          s.flags[f] = static_cast<std::uint8_t>(s.flags[f] & ~in_cavity_bit);
          members_.erase(members_.begin() + static_cast<std::ptrdiff_t>(k));
          changed = true;
        }
      }
    }
    return true;
  }

  /// Replaces the cavity by the fan of faces from the new vertex v to its boundary edges.
  /// Constrained boundary edges stay constrained; with a crossing edge (a, b), the new edges
  /// (v, a) and (v, b) are constrained. `created()` lists the new faces.
  void commit(storage& s, index_t v) {
    if (fan_at_.size() < s.pts.size()) fan_at_.resize(s.pts.size() * 2);
    collect_boundary(s);
    created_.clear();
    for (std::size_t j = 0; j < fan_.size(); ++j)
      created_.push_back(j < members_.size() ? members_[j] : s.new_slot());
    for (std::size_t j = 0; j < fan_.size(); ++j) {
      const fan_edge& e = fan_[j];
      s.write(created_[j], {v, e.u, e.w},
              {e.outside, make_ref(created_[j], 1), make_ref(created_[j], 2)},
              e.constrained ? 1 : 0);
      fan_at_[e.u] = static_cast<std::uint32_t>(j);
    }
    for (std::size_t j = 0; j < fan_.size(); ++j) {
      const face_t f = created_[j], m = created_[fan_at_[fan_[j].w]];
      s.adj[f][1] = make_ref(m, 2);
      s.adj[m][2] = make_ref(f, 1);
      if (crossing_ != crossing_none && (fan_[j].w == split_a_ || fan_[j].w == split_b_)) {
        s.set_constrained(f, 1, true);
        s.set_constrained(m, 2, true);
      }
    }
    members_.clear();
  }

  /// Before a split commit: the endpoints of the crossing edge.
  void set_split_endpoints(index_t a, index_t b) noexcept { split_a_ = a, split_b_ = b; }
  const std::vector<face_t>& created() const noexcept { return created_; }

  /// Forgets the cavity (clears the marks).
  void clear(storage& s) {
    for (const face_t f : members_)
      s.flags[f] = static_cast<std::uint8_t>(s.flags[f] & ~in_cavity_bit);
    members_.clear();
    stack_.clear();
  }

  static constexpr ref_t crossing_none = no_ref;

private:
  struct fan_edge {
    index_t u, w;
    ref_t outside;
    bool constrained;
  };

  void add(storage& s, face_t f) {
    s.flags[f] = static_cast<std::uint8_t>(s.flags[f] | in_cavity_bit);
    members_.push_back(f);
    stack_.push_back(f);
  }
  bool is_crossing(const storage& s, face_t f, int i) const {
    return crossing_ != crossing_none && (make_ref(f, i) == crossing_ || s.adj[f][i] == crossing_);
  }
  /// Edge i of cavity face f is on the boundary: no cavity face behind it, or a constrained
  /// edge (other than the crossing one) with cavity on both sides.
  bool on_boundary(const storage& s, face_t f, int i) const {
    if ((s.flags[ref_face(s.adj[f][i])] & in_cavity_bit) == 0) return true;
    return s.constrained(f, i) && !is_crossing(s, f, i);
  }
  void collect_boundary(const storage& s) {
    fan_.clear();
    for (const face_t f : members_)
      for (int i = 0; i < 3; ++i)
        if (on_boundary(s, f, i))
          fan_.push_back(
              {s.corner[f][next3(i)], s.corner[f][prev3(i)], s.adj[f][i], s.constrained(f, i)});
  }

  std::vector<face_t> members_, stack_, created_;
  std::vector<std::uint32_t> fan_at_;
  std::vector<fan_edge> fan_;
  ref_t crossing_ = crossing_none;
  index_t split_a_ = no_index, split_b_ = no_index;
};

} // namespace pdd::detail::cdt
