/// \file build.hpp
/// Implementation of pdd::decouple: checking the decomposition and collecting its separator
/// segments (the path edges).
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/decoupling/interface_split.hpp>
#include <pdd/errors.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace pdd::detail {

/// Checks the structure of d (ids in range, one tag per loop edge, loops of >= 3 vertices, no
/// reserved marker on external edges).
/// \throws pdd::decoupling_error naming the subdomain and loop. Complexity O(size of d).
inline void check_decomposition(const decomposition& d) {
  const auto n = d.vertices.size();
  const auto m = d.subdomains.size();
  if (m == 0) throw decoupling_error("the decomposition has no subdomains");
  if (!d.vertex_markers.empty() && d.vertex_markers.size() != n)
    throw decoupling_error("decomposition: vertex_markers and vertices differ in size");
  for (std::size_t s = 0; s < m; ++s) {
    const subdomain& sd = d.subdomains[s];
    const std::string where = "subdomain " + std::to_string(s);
    if (sd.loops.empty()) throw decoupling_error(where + " has no loops");
    if (sd.tags.size() != sd.loops.size())
      throw decoupling_error(where + ": tags and loops differ in size");
    for (std::size_t l = 0; l < sd.loops.size(); ++l) {
      const auto& loop = sd.loops[l];
      const std::string at = where + " loop " + std::to_string(l);
      if (loop.size() < 3) throw decoupling_error(at + " has fewer than 3 vertices");
      if (sd.tags[l].size() != loop.size())
        throw decoupling_error(at + ": one tag per edge expected");
      for (std::size_t i = 0; i < loop.size(); ++i) {
        if (loop[i] >= n) throw decoupling_error(at + ": vertex id out of range");
        const edge_tag& t = sd.tags[l][i];
        if (t.type == edge_tag::kind::external && t.marker == interface_marker)
          throw decoupling_error(at + ": input segment " + std::to_string(t.id) +
                                 " carries the marker reserved for interfaces (INT_MIN)");
        if (t.type == edge_tag::kind::interface && (t.neighbour >= m || t.neighbour == s))
          throw decoupling_error(at + " edge " + std::to_string(i) +
                                 ": interface edge with an invalid neighbour subdomain");
        if (d.vertices[loop[i]] == d.vertices[loop[(i + 1) % loop.size()]])
          throw decoupling_error(at + " edge " + std::to_string(i) + " has zero length");
      }
    }
  }
}

/// The path edge of the interface edge ab of subdomain s (tag t), oriented from its
/// lexicographically smaller end; its length is set.
inline path_edge new_path_edge(const decomposition& d, index_t a, index_t b, index_t s,
                               const edge_tag& t) {
  if (d.vertices[b] < d.vertices[a]) std::swap(a, b);
  const point pa = d.vertices[a], pb = d.vertices[b];
  path_edge e;
  e.u = a;
  e.v = b;
  e.interface_id = t.id;
  e.sides = {std::min(s, t.neighbour), std::max(s, t.neighbour)};
  e.length = std::hypot(pb.x - pa.x, pb.y - pa.y);
  return e;
}

/// Records that subdomain s (tag t) uses path edge e, already seen from the sides in
/// `seen` (bit 1: e.sides[0], bit 2: e.sides[1]).
/// \throws pdd::decoupling_error if s is not a side of e, has used it before, or names
/// another neighbour.
inline void mark_second_side(const path_edge& e, std::uint8_t& seen, index_t a, index_t b,
                             index_t s, const edge_tag& t) {
  const std::uint8_t side = s == e.sides[0] ? 1 : (s == e.sides[1] ? 2 : 4);
  if (side == 4 || (seen & side) || t.neighbour != e.sides[side == 1 ? 1 : 0])
    throw decoupling_error("interface edge between vertices " + std::to_string(a) + " and " +
                           std::to_string(b) + " (subdomain " + std::to_string(s) +
                           ") does not match its other side");
  seen |= side;
}

/// Collects the separator segments of d: one path_edge per interface loop edge pair, numbered
/// in order of first appearance (subdomains, loops and edges in order), and fills
/// loop_edge_path. Lengths are set; k, pieces and points are not.
/// \throws pdd::decoupling_error when an interface edge does not appear exactly twice, on the
/// two subdomains that name each other as neighbours. Complexity O(size of d) expected.
inline void collect_path_edges(const decomposition& d, std::vector<path_edge>& path,
                               std::vector<std::vector<index_t>>& loop_edge_path) {
  std::unordered_map<std::uint64_t, index_t> index;
  std::vector<std::uint8_t> seen;
  loop_edge_path.assign(d.subdomains.size(), {});
  for (index_t s = 0; s < d.subdomains.size(); ++s) {
    const subdomain& sd = d.subdomains[s];
    for (std::size_t l = 0; l < sd.loops.size(); ++l) {
      const auto& loop = sd.loops[l];
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const edge_tag& t = sd.tags[l][i];
        if (t.type == edge_tag::kind::external) {
          loop_edge_path[s].push_back(no_index);
          continue;
        }
        const index_t a = loop[i], b = loop[(i + 1) % loop.size()];
        const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
        const auto [it, fresh] = index.emplace(key, static_cast<index_t>(path.size()));
        if (fresh) {
          path.push_back(new_path_edge(d, a, b, s, t));
          seen.push_back(s == path.back().sides[0] ? 1 : 2);
        } else {
          mark_second_side(path[it->second], seen[it->second], a, b, s, t);
        }
        loop_edge_path[s].push_back(it->second);
      }
    }
  }
  for (std::size_t e = 0; e < path.size(); ++e)
    if (seen[e] != 3)
      throw decoupling_error("interface edge between vertices " + std::to_string(path[e].u) +
                             " and " + std::to_string(path[e].v) + " appears only in subdomain " +
                             std::to_string(seen[e] == 1 ? path[e].sides[0] : path[e].sides[1]));
}

/// Places the interface points of every path edge (e.pieces - 1 each, in path order) into
/// dd.points and records each edge's first point; the same formula on both sides of an
/// interface (interface_split_point), so both sides' vertices are bitwise identical.
inline void place_split_points(decoupled_decomposition& dd) {
  std::size_t total = 0;
  for (const path_edge& e : dd.path)
    total += e.pieces - 1;
  dd.points.reserve(dd.points.size() + total);
  for (path_edge& e : dd.path) {
    e.first_point = dd.points.size();
    const point a = dd.parts.vertices[e.u], b = dd.parts.vertices[e.v];
    for (index_t i = 1; i < e.pieces; ++i)
      dd.points.push_back(interface_split_point(a, b, i, e.pieces));
  }
}

} // namespace pdd::detail
