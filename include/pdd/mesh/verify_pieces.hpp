/// \file verify_pieces.hpp
/// pdd::verify_pieces: verifies a per-subdomain mesh (a .pvtu index over .vtu pieces or a .pddi
/// index over binary .pddm pieces, as `pdd-mesh --output-per-subdomain [--format]` and
/// pdd::piece_directory_sink write it) one piece at a time,
/// without loading the whole mesh: every piece alone as pdd::verify checks a mesh, then every
/// interface between pieces (bitwise equal shared edges, exact Delaunay across them).
#pragma once

#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/io/piece_files.hpp>
#include <pdd/mesh/detail/verify_pieces.hpp>
#include <pdd/mesh/quality_exemptions.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/sizing/any_sizing.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

namespace pdd {

/// What verify_pieces() found. Counts are exact; `messages` describe the first max_reported
/// problems, each naming its piece (file name), triangle index and coordinates.
struct pieces_report {
  /// \var pieces
  /// The number of pieces the index lists (all were read).
  /// \var triangles
  /// Total triangles over the pieces.
  /// \var vertices
  /// Total vertices summed over the pieces (an interface vertex once per piece that has it).
  std::size_t pieces = 0, triangles = 0, vertices = 0;
  /// Triangles of the largest piece (what one piece costs to hold in memory).
  std::size_t largest_piece_triangles = 0;
  std::size_t interface_edges = 0;       ///< boundary edges matched bitwise by another piece
  std::size_t domain_boundary_edges = 0; ///< unmatched boundary edges on an input segment
  std::size_t max_open_edges = 0;        ///< peak size of the table of unmatched edges
  /// \var orientation_violations
  /// Clockwise, degenerate or malformed triangles, over all pieces (as pdd::verify counts them).
  /// \var duplicate_vertices
  /// Vertices at the coordinates of an earlier one in the same piece (as pdd::verify counts
  /// them).
  /// \var quality_violations
  /// Triangles with an angle below the bound, over all pieces (quality-exempt ones excepted).
  /// \var area_violations
  /// Triangles larger than the area bound, over all pieces.
  /// \var nonmanifold_edges
  /// Edges in more than two triangles of a piece, or interior edges of a piece used twice in
  /// the same direction (as pdd::verify counts them).

  /// Violations inside the pieces (as pdd::verify counts them; piece boundary edges excepted):
  /// interior edges that are not locally Delaunay.
  std::size_t delaunay_violations = 0, orientation_violations = 0, duplicate_vertices = 0,
              quality_violations = 0, area_violations = 0, nonmanifold_edges = 0;
  /// Interface edges whose two triangles run them in the same direction (overlap).
  std::size_t interface_overlaps = 0;
  /// Interface edges that are not locally Delaunay with the triangles of both sides.
  std::size_t interface_delaunay_violations = 0;
  /// Piece boundary edges on no input segment that no other piece has (bitwise).
  std::size_t unmatched_edges = 0;
  /// \var area_domain
  /// pdd::domain_area of the PSLG (read as verify_options::rule_as_given says).
  /// \var area_mesh
  /// Sum of the triangle areas over all pieces.
  double area_domain = 0.0, area_mesh = 0.0;
  /// area_mesh and area_domain agree within verify_options::area_tolerance (relative).
  bool area_ok = false;
  /// Descriptions of the first verify_options::max_reported problems, each prefixed with its
  /// piece's file name; empty when ok().
  std::vector<std::string> messages;

  /// True if nothing was found and the total area matches the domain's.
  bool ok() const noexcept {
    return delaunay_violations == 0 && orientation_violations == 0 && duplicate_vertices == 0 &&
           quality_violations == 0 && area_violations == 0 && nonmanifold_edges == 0 &&
           interface_overlaps == 0 && interface_delaunay_violations == 0 && unmatched_edges == 0 &&
           area_ok;
  }
};

namespace detail {

/// Adds the per-piece violation counts of `from` (a verification_report or a pieces_report) to
/// r, and its messages, prefixed, while r has fewer than max_reported.
template <class Report>
void add_piece_violations(pieces_report& r, const Report& from, const std::string& prefix,
                          std::size_t max_reported) {
  r.delaunay_violations += from.delaunay_violations;
  r.orientation_violations += from.orientation_violations;
  r.duplicate_vertices += from.duplicate_vertices;
  r.quality_violations += from.quality_violations;
  r.area_violations += from.area_violations;
  r.nonmanifold_edges += from.nonmanifold_edges;
  for (const std::string& msg : from.messages)
    if (r.messages.size() < max_reported) r.messages.push_back(prefix + msg);
}

/// The per-piece checks of pdd::verify (orientation, quality outside the triangles `exemptions`
/// exempts (unless o.quality_exempt is given), area bound min(o.criteria.max_area, sizing),
/// duplicates, nonmanifold and locally Delaunay interior edges) on piece m; adds its counts and
/// messages (prefixed with `name`) to r and returns the edge table, whose one-triangle edges
/// are the piece's boundary.
inline verify_impl::edge_table check_piece(const triangle_mesh& m, const std::string& name,
                                           const quality_exemptions& exemptions,
                                           const verify_options& o, const any_sizing& sizing,
                                           pieces_report& r) {
  verify_options vo = o;
  if (!vo.quality_exempt) vo.quality_exempt = exemptions(m, o.criteria.min_angle_deg);
  verification_report local;
  violation_sink sink{local, o.max_reported};
  const auto bound_at = [&](const point& p) { return sizing.area_at(p); };
  const std::vector<std::uint8_t> flags = check_triangles(m, vo, bound_at);
  report_triangles(m, flags, sink);
  report_duplicates(m, sink);
  std::vector<char> valid(flags.size());
  for (std::size_t t = 0; t < valid.size(); ++t)
    valid[t] = !(flags[t] & tri_malformed);
  verify_impl::edge_table table(m, valid);
  for (verify_impl::edge_record& e : table.edges())
    e.on_segment = e.count == 1; // piece boundary edges: checked across the interfaces
  // A piece does not know which of its interior edges lie on input segments: every interior
  // edge is checked, as for a mesh under the diametral circle (pdd-mesh's; see verify_pieces).
  report_edges(m, table, check_edges(m, table), true, sink);
  r.area_mesh += mesh_area(m, flags);
  add_piece_violations(r, local, name + ": ", o.max_reported);
  return table;
}

/// Matches the boundary edges of piece `piece` against the open edges of earlier pieces:
/// a match is checked (opposite directions, exact Delaunay with both apexes) and closed, an
/// edge without one is opened.
inline void match_boundary(const triangle_mesh& m, const verify_impl::edge_table& table,
                           std::uint32_t piece, const std::vector<std::string>& names,
                           pieces_impl::open_edge_table& open, std::size_t max_reported,
                           pieces_report& r) {
  using verify_impl::str;
  for (const verify_impl::edge_record& e : table.edges()) {
    if (e.count != 1) continue;
    const auto& tri = m.triangles[e.tri[0]];
    const index_t apex = tri[0] != e.a && tri[0] != e.b   ? tri[0]
                         : tri[1] != e.a && tri[1] != e.b ? tri[1]
                                                          : tri[2];
    const point& from = m.vertices[e.forward[0] ? e.a : e.b];
    const point& to = m.vertices[e.forward[0] ? e.b : e.a];
    const pieces_impl::open_edge side{piece, e.tri[0], from, to, m.vertices[apex]};
    const auto inserted = open.try_emplace(pieces_impl::make_key(from, to).first, side);
    if (inserted.second) {
      r.max_open_edges = std::max(r.max_open_edges, open.size());
      continue;
    }
    const pieces_impl::open_edge other = inserted.first->second;
    open.erase(inserted.first);
    ++r.interface_edges;
    const auto where = [&] {
      return names[piece] + ": triangle " + std::to_string(e.tri[0]) + " and " +
             names[other.piece] + ": triangle " + std::to_string(other.triangle) + ", edge " +
             str(from) + " " + str(to);
    };
    const bool same_direction =
        std::bit_cast<std::uint64_t>(other.from.x) == std::bit_cast<std::uint64_t>(from.x) &&
        std::bit_cast<std::uint64_t>(other.from.y) == std::bit_cast<std::uint64_t>(from.y);
    if (same_direction) {
      ++r.interface_overlaps;
      if (r.messages.size() < max_reported)
        r.messages.push_back(where() + ": both triangles on the same side of the interface");
    } else if (pieces_impl::strictly_in_circle(from, to, side.apex, other.apex)) {
      ++r.interface_delaunay_violations;
      if (r.messages.size() < max_reported)
        r.messages.push_back(where() + ": not locally Delaunay across the interface (apex " +
                             str(other.apex) + " inside the circumcircle of the apex " +
                             str(side.apex) + ")");
    }
  }
}

/// The edges left open after the last piece: those on an input segment are domain boundary,
/// the others interface edges that no other piece has bitwise.
inline void report_unmatched(const pieces_impl::open_edge_table& open, const pslg& input,
                             const std::vector<std::string>& names, std::size_t max_reported,
                             pieces_report& r) {
  const pieces_impl::segment_index segments(input);
  std::vector<const pieces_impl::open_edge*> bad;
  for (const auto& entry : open) {
    if (segments.on_a_segment(entry.second.from, entry.second.to))
      ++r.domain_boundary_edges;
    else
      bad.push_back(&entry.second);
  }
  std::sort(bad.begin(), bad.end(), [](const auto* a, const auto* b) {
    return a->piece != b->piece ? a->piece < b->piece : a->triangle < b->triangle;
  });
  r.unmatched_edges = bad.size();
  for (const pieces_impl::open_edge* e : bad)
    if (r.messages.size() < max_reported)
      r.messages.push_back(names[e->piece] + ": triangle " + std::to_string(e->triangle) +
                           ", edge " + verify_impl::str(e->from) + " " + verify_impl::str(e->to) +
                           ": piece boundary edge on no input segment and in no other piece "
                           "(with bitwise equal endpoints)");
}

} // namespace detail

/// Verifies a per-subdomain mesh piece by piece as the pieces arrive, with pdd::verify_pieces'
/// checks (which reads them from files through it; `pdd-mesh --verify --output-per-subdomain`
/// gives it each subdomain mesh before it is written, pdd::verifying_sink): add() checks a
/// piece alone and matches its boundary edges against the pieces added before; finish()
/// reports the edges left unmatched and the area. `given` and `o` as for verify_pieces;
/// `sizing` (optional) bounds the triangle areas with o.criteria.max_area, as pdd::verify's.
/// Thread-safety: add() may run concurrently (a piece's own checks in parallel, the matching
/// under a lock); the counts are the same in any order, the messages' order is that of the
/// matching. Memory: the open boundary edges, as verify_pieces.
class pieces_verifier {
public:
  /// \throws geometry_error as pdd::validate(given).
  explicit pieces_verifier(const pslg& given, const verify_options& o = {}, any_sizing sizing = {})
      : input_(o.rule_as_given ? given : domain_as_generated(given)), options_(o),
        sizing_(std::move(sizing)), exemptions_(input_) {
    report_.area_domain = domain_area(input_);
  }

  /// Checks piece number `piece` (distinct per piece; messages name it `name`).
  void add(std::uint32_t piece, const std::string& name, const triangle_mesh& m) {
    pieces_report own;
    const auto table = detail::check_piece(m, name, exemptions_, options_, sizing_, own);
    const std::scoped_lock lock(mutex_);
    if (names_.size() <= piece) names_.resize(piece + 1);
    names_[piece] = name;
    count(m, own);
    detail::match_boundary(m, table, piece, names_, open_, options_.max_reported, report_);
  }

  /// The report over the pieces added: the boundary edges still open are domain boundary (on an
  /// input segment) or unmatched, and the areas must agree. Call once, after the last add().
  pieces_report finish() {
    const std::scoped_lock lock(mutex_);
    pieces_report& r = report_;
    detail::report_unmatched(open_, input_, names_, options_.max_reported, r);
    r.area_ok =
        std::abs(r.area_mesh - r.area_domain) <= options_.area_tolerance * std::abs(r.area_domain);
    if (!r.area_ok && r.messages.size() < options_.max_reported)
      r.messages.push_back("total area of the pieces " + std::to_string(r.area_mesh) +
                           " differs from the domain area " + std::to_string(r.area_domain));
    return r;
  }

private:
  /// Adds a piece's own counts and messages (check_piece's) to the report.
  void count(const triangle_mesh& m, const pieces_report& own) {
    pieces_report& r = report_;
    ++r.pieces;
    r.triangles += m.triangles.size();
    r.vertices += m.vertices.size();
    r.largest_piece_triangles = std::max(r.largest_piece_triangles, m.triangles.size());
    r.area_mesh += own.area_mesh;
    detail::add_piece_violations(r, own, "", options_.max_reported);
  }

  pslg input_;
  verify_options options_;
  any_sizing sizing_;
  quality_exemptions exemptions_; // once, not per piece
  std::mutex mutex_;
  std::vector<std::string> names_; // by piece number
  detail::pieces_impl::open_edge_table open_;
  pieces_report report_;
};

/// Verifies the per-subdomain mesh indexed by the .pvtu or .pddi at `index` (the format told
/// from the files, pdd::read_piece_index and pdd::read_piece) against the input PSLG
/// `input` (the PSLG it meshes, read as pdd::verify reads it: pdd::domain_as_generated unless
/// o.rule_as_given) and o.criteria (min_angle_deg, uniform max_area; pieces carry no sizing
/// field): each piece alone with pdd::verify's checks (orientation, angle bound outside the
/// triangles pdd's one rule exempts, pdd::quality_exemptions, area bound, duplicate vertices,
/// nonmanifold edges, exact local Delaunay of its interior edges); then each piece boundary
/// edge must appear in exactly one other piece with bitwise equal endpoints in the opposite
/// direction and be locally Delaunay with the triangles of both sides (exact
/// side_of_oriented_circle), or lie on an input segment (verify_impl::on_segment_line); and
/// the pieces' areas must sum to domain_area(input) within o.area_tolerance.
/// Not checked (pieces carry no segments): that input segments inside one piece are unions of
/// its edges. For the same reason every interior edge of a piece must be locally Delaunay,
/// whatever o.criteria.encroachment says: per-subdomain meshes are pdd-mesh's, made under the
/// diametral circle.
/// Memory: one piece at a time, plus the open boundary edges (each piece's boundary edges
/// wait in a hash table, keyed by their endpoints' bits, until the neighbour's piece closes
/// them): O(largest piece + boundary edges of all pieces) at worst, reported as max_open_edges.
/// \throws pdd::error naming the file for an unreadable, truncated, tampered (binary: its
/// checksum) or foreign index or piece;
/// geometry_error as pdd::validate(input). Complexity: O(total size) expected.
inline pieces_report verify_pieces(const std::filesystem::path& index, const pslg& given,
                                   const verify_options& o = {}) {
  pieces_verifier verifier(given, o);
  const std::vector<std::filesystem::path> files = read_piece_index(index);
  for (std::size_t k = 0; k < files.size(); ++k)
    verifier.add(static_cast<std::uint32_t>(k), files[k].filename().string(), read_piece(files[k]));
  return verifier.finish();
}

} // namespace pdd
