/// \file children.hpp
/// Implementation detail of MADD's split step: the boundary of one part of a bisection of
/// the cells, linked vertex to vertex, traced into loops, and assembled into a child region
/// (outer loop first).
#pragma once

#include <pdd/madd/detail/graph.hpp>
#include <pdd/madd/detail/region.hpp>
#include <pdd/madd/detail/triangulation.hpp>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace pdd::detail {

/// The boundary links of one part of a bisection: next[v] is the vertex after v on the part's
/// boundary (z vertices, then circumcentres nz + t), sep[v] whether that edge is a separator
/// piece, starts the vertices with a link.
struct part_boundary {
  std::vector<std::uint32_t> next;
  std::vector<char> sep;
  std::vector<std::uint32_t> starts;
};

/// The ends (from, to) of side s of a cell, counter-clockwise; circumcentres are nz + t.
inline std::pair<std::uint32_t, std::uint32_t>
cell_side_ends(const madd_triangulation& tr, const madd_cell& cell, std::uint32_t nz, int s) {
  const auto& v = tr.faces[cell.tri].v;
  if (cell.sub < 0) return {v[(s + 1) % 3], v[(s + 2) % 3]};
  const std::uint32_t cc = nz + cell.tri;
  const std::uint32_t a = v[(cell.sub + 1) % 3], b = v[(cell.sub + 2) % 3];
  return {s == 0 ? a : s == 1 ? b : cc, s == 0 ? b : s == 1 ? cc : a};
}

/// Links the boundary of part p (the sides of its cells not shared with p); marks the z
/// vertices on separator pieces in used_by_separator. False on a pinch (two links from one
/// vertex).
inline bool link_part_boundary(const madd_triangulation& tr, const madd_graph& g,
                               const std::vector<std::uint8_t>& part, std::uint8_t p,
                               part_boundary& b, std::vector<char>& used_by_separator) {
  const auto nz = static_cast<std::uint32_t>(tr.z.size());
  std::fill(b.next.begin(), b.next.end(), no_index);
  b.starts.clear();
  for (std::uint32_t c = 0; c < g.cells.size(); ++c) {
    if (part[c] != p) continue;
    const madd_cell& cell = g.cells[c];
    for (int s = 0; s < 3; ++s) {
      const auto [from, to] = cell_side_ends(tr, cell, nz, s);
      const std::int32_t fi = cell.side[s];
      bool is_sep = false;
      if (fi >= 0) {
        const madd_cell_face& f = g.faces[fi];
        const std::uint32_t other = f.a == c ? f.b : f.a;
        if (part[other] == p) continue;
        PDD_ASSERT(f.cuttable);
        is_sep = true;
      }
      if (b.next[from] != no_index) return false; // pinch
      b.next[from] = to;
      b.sep[from] = is_sep ? 1 : 0;
      b.starts.push_back(from);
      if (is_sep) {
        if (from < nz) used_by_separator[from] = 1;
        if (to < nz) used_by_separator[to] = 1;
      }
    }
  }
  return true;
}

/// Follows the boundary links from s0 into one loop of a child, dropping refinement vertices
/// between two boundary pieces. False if the links do not close into a simple cycle.
inline bool trace_child_loop(const madd_region& r, const madd_triangulation& tr,
                             const madd_graph& g, const part_boundary& b, std::uint32_t s0,
                             std::vector<char>& done, madd_loop& loop) {
  const auto nz = static_cast<std::uint32_t>(tr.z.size());
  std::vector<std::uint32_t> cyc;
  std::uint32_t v = s0;
  do {
    if (done[v] || b.next[v] == no_index) return false;
    done[v] = 1;
    cyc.push_back(v);
    v = b.next[v];
  } while (v != s0);
  const std::size_t m = cyc.size();
  for (std::size_t i = 0; i < m; ++i) {
    const std::uint32_t x = cyc[i];
    const std::uint32_t prev = cyc[(i + m - 1) % m];
    if (x < nz && !tr.z[x].original && !b.sep[x] && !b.sep[prev]) continue;
    loop.points.push_back(x < nz ? tr.z[x].p : g.info[x - nz].c);
    loop.markers.push_back(x < nz ? tr.z[x].marker : 0);
    if (b.sep[x]) {
      loop.tags.push_back(madd_edge_tag{});
    } else {
      const madd_zvertex& zx = tr.z[x];
      loop.tags.push_back(r.loops[zx.loop].tags[zx.edge]);
    }
  }
  return true;
}

/// Assembles one child from its linked boundary: its loops with the one counter-clockwise
/// (outer) loop first, and its area. False unless there is exactly one outer loop and every
/// loop has at least 3 vertices.
inline bool assemble_child(const madd_region& r, const madd_triangulation& tr, const madd_graph& g,
                           part_boundary& b, madd_region& child) {
  std::sort(b.starts.begin(), b.starts.end());
  std::vector<char> done(b.next.size(), 0);
  int outer = -1;
  for (const std::uint32_t s0 : b.starts) {
    if (done[s0]) continue;
    madd_loop loop;
    if (!trace_child_loop(r, tr, g, b, s0, done, loop)) return false;
    if (loop.size() < 3) return false;
    if (polygon_signed_area(loop.points) > 0.0) {
      if (outer >= 0) return false;
      outer = static_cast<int>(child.loops.size());
    }
    child.loops.push_back(std::move(loop));
  }
  if (outer < 0) return false;
  std::rotate(child.loops.begin(), child.loops.begin() + outer, child.loops.begin() + outer + 1);
  child.area = region_area(child);
  return true;
}

} // namespace pdd::detail
