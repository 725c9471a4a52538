// Tampering with a per-subdomain output (VTU or binary pieces) for the tests of pdd-verify and
// pdd::verify_pieces: reading all pieces, finding the interface edges, flipping an edge across
// an interface and moving an interface vertex by one ulp, and writing a piece back in its
// format (with a valid checksum for binary pieces: only the geometry is wrong).
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/io/piece_files.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace pdd::test {

/// The bits of a point's coordinates (interface vertices are compared bitwise).
using point_bits = std::array<std::uint64_t, 2>;
inline point_bits bits(const pdd::point& p) {
  return {std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(p.y)};
}

/// One side of an interface edge: piece, triangle, and the position of the edge's first
/// vertex in the triangle (the edge runs tri[i] -> tri[i + 1]).
struct edge_side {
  std::size_t piece, triangle;
  int i;
};

/// The interface edges of the pieces: directed edge (from, to) of one piece whose reverse is
/// in another piece; returns pairs (this side, the other side).
inline std::vector<std::pair<edge_side, edge_side>>
interface_edges(const std::vector<pdd::triangle_mesh>& pieces) {
  std::map<std::pair<point_bits, point_bits>, edge_side> directed;
  for (std::size_t k = 0; k < pieces.size(); ++k)
    for (std::size_t t = 0; t < pieces[k].triangles.size(); ++t)
      for (int i = 0; i < 3; ++i) {
        const auto& tri = pieces[k].triangles[t];
        directed[{bits(pieces[k].vertices[tri[i]]), bits(pieces[k].vertices[tri[(i + 1) % 3]])}] = {
            k, t, i};
      }
  std::vector<std::pair<edge_side, edge_side>> out;
  for (const auto& [edge, s] : directed) {
    const auto other = directed.find({edge.second, edge.first});
    if (other != directed.end() && other->second.piece != s.piece && edge.first < edge.second)
      out.push_back({s, other->second});
  }
  return out;
}

/// Every piece of the per-subdomain output indexed by `index` (.pvtu or .pddi), in index order.
inline std::vector<pdd::triangle_mesh> read_all_pieces(const std::filesystem::path& index) {
  std::vector<pdd::triangle_mesh> pieces;
  for (const std::filesystem::path& p : pdd::read_piece_index(index))
    pieces.push_back(pdd::read_piece(p));
  return pieces;
}

/// Flips the first interface edge whose two triangles form a convex quadrilateral: p's
/// triangle a -> b -> c and q's b -> a -> d become (a, d, c) and (d, b, c), each piece gaining
/// the other's apex. Returns the pieces changed (first: the one named in the message), or
/// {npos, npos} when no edge qualifies.
inline std::pair<std::size_t, std::size_t>
flip_an_interface_edge(std::vector<pdd::triangle_mesh>& pieces) {
  for (const auto& [p, q] : interface_edges(pieces)) {
    auto& mp = pieces[p.piece];
    auto& mq = pieces[q.piece];
    const auto tp = mp.triangles[p.triangle];
    const auto tq = mq.triangles[q.triangle];
    const pdd::point a = mp.vertices[tp[p.i]], b = mp.vertices[tp[(p.i + 1) % 3]],
                     c = mp.vertices[tp[(p.i + 2) % 3]], d = mq.vertices[tq[(q.i + 2) % 3]];
    const auto left = [](const pdd::point& u, const pdd::point& v, const pdd::point& w) {
      return (v.x - u.x) * (w.y - u.y) - (v.y - u.y) * (w.x - u.x) > 1e-12;
    };
    if (!left(a, d, c) || !left(d, b, c)) continue;
    const auto add = [](pdd::triangle_mesh& m, const pdd::point& v) {
      m.vertices.push_back(v);
      m.vertex_markers.push_back(0);
      return static_cast<pdd::index_t>(m.vertices.size() - 1);
    };
    mp.triangles[p.triangle] = {tp[p.i], add(mp, d), tp[(p.i + 2) % 3]};
    const pdd::index_t qb = tq[q.i], qc = add(mq, c);
    mq.triangles[q.triangle] = {tq[(q.i + 2) % 3], qb, qc};
    return {p.piece, q.piece};
  }
  return {std::string::npos, std::string::npos};
}

/// Moves the first vertex of the middle interface edge by one ulp in x in its first side's
/// piece; returns that side.
inline edge_side move_an_interface_vertex(std::vector<pdd::triangle_mesh>& pieces) {
  const auto edges = interface_edges(pieces);
  const edge_side s = edges.at(edges.size() / 2).first;
  auto& m = pieces[s.piece];
  pdd::point& v = m.vertices[m.triangles[s.triangle][s.i]];
  v.x = std::nextafter(v.x, INFINITY);
  return s;
}

} // namespace pdd::test
