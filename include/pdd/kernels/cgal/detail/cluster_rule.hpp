/// \file cluster_rule.hpp
/// The edge level's cluster rule of pdd::cgal::mesher, restricted to small angles of the domain.
///
/// Root cause of the unshielded bad triangles of issue 11 (../shared/data/regressions/
/// quality-*.poly): CGAL Mesh_2 groups the constrained edges around a vertex into a *cluster*
/// wherever two consecutive ones make an angle below 60 deg (Shewchuk's treatment of small
/// input angles), without looking at the domain. Once a cluster is reduced, a bad face whose
/// circumcentre encroaches one of its segments is dropped for good, not refined, when its
/// shortest edge is longer than the cluster's shortest (Refine_edges_base_with_clusters::
/// test_point_conflict_from_superior_impl returns CONFLICT_AND_ELEMENT_SHOULD_BE_DROPPED). That
/// exemption is meant for skinny faces inside a small angle of the domain. But an angle below
/// 60 deg on the side of a vertex that is *not* in the domain (a sharp corner of a hole, a
/// sharp notch in the outer loop: a reflex domain corner whose exterior angle is below 60 deg)
/// makes a cluster too, and then in-domain faces near that corner, which nothing shields, were
/// dropped with angles down to 8 deg. Every domain has such corners once small domain angles
/// are shielded (dissertation 8.1 leaves D' with none below 60 deg on the domain side, so no
/// cluster of D' may ever drop a face), and subdomain corners of the decoupled path are the same.
///
/// An exterior wedge needs no cluster: pdd's encroachment test (domain_gabriel) only counts
/// vertices on a domain side of a segment, and a vertex on one segment of an exterior wedge lies
/// on the outer side of the other, so the two segments can never encroach each other (the
/// ping-pong that clusters exist to stop). The rule below is CGAL's on the run of small
/// angles in the domain that the encroached segment bounds (domain_cluster), not on CGAL's
/// whole cluster, which may span exterior wedges: a face is dropped only when that run exists,
/// is reduced, and its rmin is below the face's shortest edge; otherwise the encroached
/// segment is split and the face is reconsidered, as in Ruppert's algorithm.
///
/// Domains that are not of closed loops (internal and dangling constraints, issue 13) meshed
/// whole are unshielded, since pdd's shields are built on closed loops: there the clusters are
/// the remedy for small angles between constraints inside the domain (concentric shells, as in
/// Triangle), and the faces this rule leaves are the documented exemption
/// (pdd::find_cluster_exempt_triangles, mesh/cluster_exempt.hpp). Decoupled, such a small
/// angle lies inside one subdomain (a segment inside a face, with MADD's separators kept away
/// from it; a corner with such a segment at its apex is left unshielded): its clusters split
/// only that subdomain's own segments, and the pipeline's invariance check would catch a
/// split interface piece (none was seen in the tests).
#pragma once

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Mesh_2/Clusters.h>
#include <CGAL/Mesh_2/Refine_edges_with_clusters.h>
#include <CGAL/Mesher_level.h>
#include <CGAL/Meshes/Triangulation_mesher_level_traits_2.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <tuple>
#include <vector>

namespace pdd::detail::cgal_mesh {

/// The part of a cluster that one of its segments can interact with (see domain_cluster):
/// whether the segment bounds a small angle in the domain, whether that part is reduced, and
/// its rmin.
struct domain_cluster_state {
  bool meets_domain = false; ///< the segment bounds a small angle of the cluster in the domain
  bool reduced = true;       ///< every segment of the part has been split on a shell
  double rmin = 0.0;         ///< min over the part's angles of |x y|^2 / 4 (CGAL's rmin, squared)
};

/// The sectors of v between counter-clockwise consecutive constrained edges (v, x) and (v, y),
/// in order, each with whether it is a small angle of cluster c in the domain: both edges in
/// the cluster, CGAL's small-angle test true, its faces in the domain. Complexity O(degree).
template <class Tr>
std::vector<std::tuple<typename Tr::Vertex_handle, typename Tr::Vertex_handle, bool>>
cluster_sectors(const Tr& tr, const CGAL::Mesh_2::Clusters<Tr>& clusters,
                typename Tr::Vertex_handle v,
                const typename CGAL::Mesh_2::Clusters<Tr>::Cluster& c) {
  std::vector<std::tuple<typename Tr::Vertex_handle, typename Tr::Vertex_handle, bool>> out;
  // A face (v, a, b), counter-clockwise, follows the edge (v, a) and precedes (v, b).
  auto fc = tr.incident_faces(v);
  const auto first = fc;
  while (!fc->is_constrained(Tr::cw(fc->index(v))))
    if (++fc == first) return out; // no constrained edge at v
  const auto start = fc;
  do {
    const auto x = fc->vertex(Tr::ccw(fc->index(v)));
    bool in_domain = false;
    bool closed = false;
    typename Tr::Vertex_handle y;
    do {
      const int i = fc->index(v);
      in_domain = in_domain || (!tr.is_infinite(fc) && fc->is_in_domain());
      y = fc->vertex(Tr::cw(i));
      closed = fc->is_constrained(Tr::ccw(i));
      ++fc;
    } while (!closed);
    out.emplace_back(x, y,
                     in_domain && c.vertices.count(x) != 0 && c.vertices.count(y) != 0 &&
                         clusters.is_small_angle(x->point(), v->point(), y->point()));
  } while (fc != start);
  return out;
}

/// The part of the cluster c of v (CGAL's: the constrained edges from v to c.vertices,
/// consecutive ones counter-clockwise less than 60 deg apart) that its segment (v, w) can
/// interact with: the run of consecutive small angles of c in the domain that (v, w) bounds.
///
/// Why not CGAL's own is_reduced() and rmin: CGAL's cluster also spans the small angles outside
/// the domain (a sharp hole touching v). pdd's encroachment test (domain_gabriel) never lets a
/// segment encroach another across such a hole, so the segments on either side of it are
/// split independently, and those that nothing encroaches are never split: CGAL's cluster
/// then never became reduced, its faces in the domain were never dropped, and the shells went
/// on shrinking until the split points rounded off their segments (a hole of 31 deg beside a
/// sector of 14 deg at one vertex; four holes 20-50 deg apart at another: a non-finite
/// circumcentre, a floating point exception, or no end). A run of small angles in the domain
/// is what can encroach each other, Shewchuk's cluster proper: it is reduced when each of its
/// segments has been split on a shell. Complexity O(degree of v log).
template <class Tr>
domain_cluster_state domain_cluster(const Tr& tr, const CGAL::Mesh_2::Clusters<Tr>& clusters,
                                    typename Tr::Vertex_handle v, typename Tr::Vertex_handle w,
                                    const typename CGAL::Mesh_2::Clusters<Tr>::Cluster& c) {
  domain_cluster_state out;
  const auto sectors = cluster_sectors(tr, clusters, v, c);
  const std::size_t m = sectors.size();
  std::size_t at = m;
  for (std::size_t i = 0; i < m && at == m; ++i)
    if (std::get<2>(sectors[i]) && (std::get<0>(sectors[i]) == w || std::get<1>(sectors[i]) == w))
      at = i;
  if (at == m) return out;
  std::size_t before = 0; // small angles of the run before sector `at`
  while (before + 1 < m && std::get<2>(sectors[(at + m - before - 1) % m]))
    ++before;
  const auto split_on_shell = [&](typename Tr::Vertex_handle x) {
    const auto it = c.vertices.find(x);
    return it != c.vertices.end() && it->second;
  };
  out.meets_domain = true;
  out.rmin = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < m; ++k) {
    const auto& [x, y, small] = sectors[(at + m - before + k) % m];
    if (!small) break;
    out.rmin = std::min(out.rmin, CGAL::squared_distance(x->point(), y->point()) / 4.0);
    out.reduced = out.reduced && split_on_shell(x) && split_on_shell(y);
  }
  return out;
}

/// CGAL's Refine_edges_base_with_clusters with its cluster rule restricted to clusters that
/// meet the domain (see the file comment for why).
/// \tparam Tr a CGAL constrained Delaunay triangulation with Delaunay_mesh_face_base_2 faces.
/// \tparam Conform the encroachment test (Is_locally_conforming_Gabriel's interface).
template <class Tr, class Conform>
class domain_cluster_edges_base
    : public CGAL::Mesh_2::Refine_edges_base_with_clusters<Tr, Conform> {
  using super = CGAL::Mesh_2::Refine_edges_base_with_clusters<Tr, Conform>;
  using clusters_type = CGAL::Mesh_2::Clusters<Tr>;
  using Zone = typename CGAL::Triangulation_mesher_level_traits_2<Tr>::Zone;
  using Face_handle = typename Tr::Face_handle;

public:
  domain_cluster_edges_base(Tr& t, clusters_type& c) : super(t, c), clusters_(c) {}

  /// The segments on the boundary of the conflict zone of p (a bad face's circumcentre) that p
  /// encroaches are queued for splitting, and the face is reconsidered afterwards; the face is
  /// dropped instead (CGAL's rule, not imperative refinement) when such a segment belongs to
  /// one reduced cluster that meets the domain and whose shortest edge is shorter than the
  /// face's shortest edge. As in CGAL, the status of the last encroached segment is returned.
  CGAL::Mesher_level_conflict_status
  test_point_conflict_from_superior_impl(const typename Tr::Point& p, Zone& z) {
    CGAL::Mesher_level_conflict_status status = CGAL::NO_CONFLICT;
    const double shortest = shortest_squared_edge(z.parent_face);
    for (const auto& e : z.boundary_edges) {
      const Face_handle& fh = e.first;
      const int i = e.second;
      if (!fh->is_constrained(i)) continue;
      const bool encroaches = !this->is_locally_conform(this->tr, fh, i, p);
      // Under the lens a point can lie beyond a segment without encroaching it (never under
      // the disk, Ruppert's lemma): the segment is split, as the disk would have had it split
      // by the face's own apex, and the cluster rule does not leave the face.
      if (!encroaches && !this->is_locally_conform.hides(this->tr, fh, i, p)) continue;
      const auto v1 = fh->vertex(Tr::cw(i));
      const auto v2 = fh->vertex(Tr::ccw(i));
      status = encroaches && drops_face(v1, v2, shortest)
                   ? CGAL::CONFLICT_AND_ELEMENT_SHOULD_BE_DROPPED
                   : CGAL::CONFLICT_BUT_ELEMENT_CAN_BE_RECONSIDERED;
      if (status != CGAL::CONFLICT_AND_ELEMENT_SHOULD_BE_DROPPED)
        this->add_constrained_edge_to_be_conformed(v1, v2);
    }
    return status;
  }

private:
  /// CGAL's condition for leaving a bad face whose circumcentre encroaches [v1, v2], on the
  /// cluster's small angles in the domain (domain_cluster).
  bool drops_face(typename Tr::Vertex_handle v1, typename Tr::Vertex_handle v2,
                  double shortest) const {
    typename clusters_type::Cluster c1, c2;
    typename clusters_type::const_iterator it;
    const bool at1 = clusters_.get_cluster(v1, v2, c1, it);
    const bool at2 = clusters_.get_cluster(v2, v1, c2, it);
    if (at1 == at2 || this->imperatively) return false;
    const domain_cluster_state c = at1 ? domain_cluster(this->tr, clusters_, v1, v2, c1)
                                       : domain_cluster(this->tr, clusters_, v2, v1, c2);
    return c.meets_domain && c.reduced && c.rmin < shortest;
  }

  double shortest_squared_edge(const Face_handle& f) const {
    const auto dist = this->tr.geom_traits().compute_squared_distance_2_object();
    const auto& a = f->vertex(0)->point();
    const auto& b = f->vertex(1)->point();
    const auto& c = f->vertex(2)->point();
    return std::min({dist(b, c), dist(c, a), dist(a, b)});
  }

  const clusters_type& clusters_;
};

} // namespace pdd::detail::cgal_mesh
