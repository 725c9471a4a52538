/// \file insertion.hpp
/// Vertex insertion into the native triangulation by Bowyer-Watson cavities (Bowyer 1981,
/// Watson 1981), constrained: a cavity grows from seed triangles across unconstrained edges to
/// every triangle whose circumcircle contains the new point strictly, and is then shrunk until
/// it is star-shaped from the point (a triangle behind a segment, reached around the segment's
/// end, is not visible from the point and stays: Chew's constrained Delaunay condition).
#pragma once

#include <pdd/errors.hpp>
#include <pdd/kernels/native/detail/triangulation.hpp>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace pdd::detail::native_mesh {

/// The scratch arrays of cavity construction (reused: no allocation per insertion once grown).
class cavity {
public:
  /// Grows the cavity of p from `seeds` (triangles whose circumcircle contains p or that
  /// contain p). `crossing` (or no_ref) is a constrained edge between two seeds that p splits.
  void grow(triangulation& tr, const point& p, std::initializer_list<std::uint32_t> seeds,
            ref_t crossing) {
    clear(tr);
    crossing_ = crossing;
    bounded_by_segment_ = false;
    for (const std::uint32_t s : seeds)
      add(tr, s);
    while (!stack_.empty()) {
      const std::uint32_t t = stack_.back();
      stack_.pop_back();
      for (int i = 0; i < 3; ++i) {
        const ref_t n = tr.adj(t)[i];
        if (n == no_ref || tr.constrained(t, i)) {
          bounded_by_segment_ = true;
          continue;
        }
        const std::uint32_t u = ref_tri(n);
        if ((tr.flags(u) & in_cavity_bit) == 0 &&
            in_circle(tr.at(u, 0), tr.at(u, 1), tr.at(u, 2), p))
          add(tr, u);
      }
    }
  }

  /// The constrained edges on the cavity's boundary that p encroaches (`encroaches(t, i, p)`
  /// for edge i of cavity triangle t: in its diametral disk or lens) or that hide p (p not
  /// strictly on the cavity's side), as edge references.
  template <class Encroaches>
  const std::vector<ref_t>& encroached_segments(const triangulation& tr, const point& p,
                                                Encroaches encroaches) {
    encroached_.clear();
    if (!bounded_by_segment_) return encroached_;
    for (const std::uint32_t t : members_)
      for (int i = 0; i < 3; ++i) {
        if (!tr.constrained(t, i) || make_ref(t, i) == crossing_ || is_crossing_twin(tr, t, i))
          continue;
        if (orient(tr.at(t, next3(i)), tr.at(t, prev3(i)), p) <= 0 || encroaches(t, i, p))
          encroached_.push_back(make_ref(t, i));
      }
    return encroached_;
  }

  /// Removes triangles until every boundary edge sees p strictly on the cavity's side.
  /// \returns false when a seed would have to go (p is not visible from the seeds).
  /// A cavity that no segment (nor the bounding triangle's outer edge) bounds or crosses is
  /// star-shaped already: across each boundary edge e, unconstrained and so locally Delaunay,
  /// the open circumdisk of the cavity triangle beyond e's line (or on e itself) lies in the
  /// open circumdisk of the triangle outside, which p would then have entered; so p is
  /// strictly on the cavity's side of e, and no test is needed.
  bool make_star_shaped(triangulation& tr, const point& p, std::size_t seeds) {
    if (!bounded_by_segment_) return true;
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t k = 0; k < members_.size() && !changed; ++k) {
        const std::uint32_t t = members_[k];
        for (int i = 0; i < 3 && !changed; ++i) {
          if (!on_boundary(tr, t, i)) continue;
          if (orient(tr.at(t, next3(i)), tr.at(t, prev3(i)), p) > 0) continue;
          if (k < seeds) return false;
          tr.flags(t) = static_cast<std::uint8_t>(tr.flags(t) & ~in_cavity_bit);
          members_.erase(members_.begin() + static_cast<std::ptrdiff_t>(k));
          changed = true;
        }
      }
    }
    return true;
  }

  /// Replaces the cavity by the fan of triangles from the new vertex v (in tr.pts) to its
  /// boundary edges. Constrained boundary edges stay constrained; each new triangle inherits
  /// the in-domain flag of the triangle whose boundary edge it takes. With a crossing edge
  /// (a, b), the new edges (v, a) and (v, b) are constrained. `created()` lists the new
  /// triangles. Complexity O(cavity size) (a small fan is linked by search, a large one
  /// through a table by vertex).
  void commit(triangulation& tr, index_t v) {
    if (tr.vertex_tri.size() < tr.pts.size()) tr.vertex_tri.resize(tr.pts.size());
    collect_boundary(tr);
    created_.clear();
    for (std::size_t j = 0; j < fan_.size(); ++j)
      created_.push_back(j < members_.size() ? members_[j] : tr.new_slot());
    for (std::size_t j = 0; j < fan_.size(); ++j) {
      const fan_edge& e = fan_[j];
      const std::uint32_t t = created_[j];
      tr.slots[t] = {{v, e.u, e.w}, {e.outside, no_ref, no_ref}, e.flags};
      if (e.outside != no_ref) tr.adj(ref_tri(e.outside))[ref_edge(e.outside)] = make_ref(t, 0);
      tr.vertex_tri[e.u] = t;
    }
    tr.vertex_tri[v] = created_.front();
    link_fan(tr);
    members_.clear();
  }

  /// Before a split commit: the endpoints of the crossing edge.
  void set_split_endpoints(index_t a, index_t b) noexcept { split_a_ = a, split_b_ = b; }
  const std::vector<std::uint32_t>& created() const noexcept { return created_; }
  const std::vector<std::uint32_t>& members() const noexcept { return members_; }

  /// Forgets the cavity (clears the marks).
  void clear(triangulation& tr) {
    for (const std::uint32_t t : members_)
      tr.flags(t) = static_cast<std::uint8_t>(tr.flags(t) & ~in_cavity_bit);
    members_.clear();
    stack_.clear();
  }

private:
  struct fan_edge {
    index_t u, w;
    ref_t outside;
    std::uint8_t flags;
  };

  void add(triangulation& tr, std::uint32_t t) {
    tr.flags(t) = static_cast<std::uint8_t>(tr.flags(t) | in_cavity_bit);
    members_.push_back(t);
    stack_.push_back(t);
  }
  bool is_crossing_twin(const triangulation& tr, std::uint32_t t, int i) const {
    return crossing_ != no_ref && tr.adj(t)[i] == crossing_;
  }
  /// Edge i of cavity triangle t is on the boundary: no cavity triangle behind it, or a
  /// constrained edge (other than the crossing one) with cavity on both sides.
  bool on_boundary(const triangulation& tr, std::uint32_t t, int i) const {
    const ref_t n = tr.adj(t)[i];
    if (n == no_ref || (tr.flags(ref_tri(n)) & in_cavity_bit) == 0) return true;
    return tr.constrained(t, i) && make_ref(t, i) != crossing_ && !is_crossing_twin(tr, t, i);
  }
  /// The fan triangle whose edge (v, u) has u == w: a search in a small fan, a table by
  /// vertex in a large one (a random access into an array as long as the vertices).
  template <class Find>
  void link_each(triangulation& tr, Find find) {
    for (std::size_t j = 0; j < fan_.size(); ++j) {
      const std::uint32_t t = created_[j], m = created_[find(fan_[j].w)];
      tr.adj(t)[1] = make_ref(m, 2);
      tr.adj(m)[2] = make_ref(t, 1);
      if (crossing_ != no_ref && (fan_[j].w == split_a_ || fan_[j].w == split_b_)) {
        tr.set_constrained(t, 1, true);
        tr.set_constrained(m, 2, true);
      }
    }
  }
  /// Links the fan's triangles to each other: triangle j = (v, u_j, w_j) meets the one whose
  /// u is w_j across the edge (v, w_j).
  void link_fan(triangulation& tr) {
    if (fan_.size() <= 32) {
      link_each(tr, [this](index_t w) {
        std::size_t m = 0;
        while (m < fan_.size() && fan_[m].u != w)
          ++m;
        // The boundary of a cavity is closed: every edge's end starts another edge.
        if (m == fan_.size())
          throw meshing_error(-1, "internal error: a cavity's boundary is not closed");
        return m;
      });
      return;
    }
    if (fan_at_.size() < tr.pts.size()) fan_at_.resize(tr.pts.size() * 2);
    for (std::size_t j = 0; j < fan_.size(); ++j)
      fan_at_[fan_[j].u] = static_cast<std::uint32_t>(j);
    link_each(tr, [this](index_t w) { return fan_at_[w]; });
  }
  void collect_boundary(const triangulation& tr) {
    fan_.clear();
    for (const std::uint32_t t : members_)
      for (int i = 0; i < 3; ++i)
        if (on_boundary(tr, t, i))
          fan_.push_back({tr.corner(t)[next3(i)], tr.corner(t)[prev3(i)], tr.adj(t)[i],
                          static_cast<std::uint8_t>((tr.flags(t) & in_domain_bit) |
                                                    (tr.constrained(t, i) ? 1 : 0))});
  }

  std::vector<std::uint32_t> members_, stack_, created_, fan_at_;
  std::vector<fan_edge> fan_;
  std::vector<ref_t> encroached_;
  ref_t crossing_ = no_ref;
  bool bounded_by_segment_ = false; ///< grow met a constrained or outer edge
  index_t split_a_ = no_index, split_b_ = no_index;
};

} // namespace pdd::detail::native_mesh
