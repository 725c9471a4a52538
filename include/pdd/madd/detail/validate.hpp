/// \file validate.hpp
/// Implementation of pdd::validate_decomposition: the checks of one subdomain, of the edges
/// (external on their input segment, interfaces twice with matching tags), of the input
/// segments' coverage and of the interface curves.
#pragma once

#include <pdd/core/bbox.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/core/kernel.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/box_pairs.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/madd/decomposition_report.hpp>
#include <pdd/madd/detail/region.hpp>

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace pdd::detail {

/// True if the loop edges ab and ce of a subdomain clash: the same edge twice, two edges
/// with a common endpoint that fold onto each other (collinear, acute), or disjoint-ended
/// edges that intersect. Exact predicates.
inline bool loop_edges_clash(const decomposition& d, index_t a, index_t b, index_t c, index_t e) {
  const epick::Point_2 pa(d.vertices[a].x, d.vertices[a].y), pb(d.vertices[b].x, d.vertices[b].y);
  const epick::Point_2 pc(d.vertices[c].x, d.vertices[c].y), pe(d.vertices[e].x, d.vertices[e].y);
  const int shared = (a == c) + (a == e) + (b == c) + (b == e);
  if (shared >= 2) return true; // the same edge twice
  if (shared == 1) {
    const index_t v = (a == c || a == e) ? a : b;
    const epick::Point_2 pv(d.vertices[v].x, d.vertices[v].y);
    const epick::Point_2& p = v == a ? pb : pa;
    const epick::Point_2& q = (v == c) ? pe : pc;
    return CGAL::collinear(pv, p, q) && CGAL::angle(p, pv, q) == CGAL::ACUTE;
  }
  return CGAL::do_intersect(epick::Segment_2(pa, pb), epick::Segment_2(pc, pe));
}

/// Segment intersections inside one subdomain (all its loops together): two edges may only
/// share an endpoint, and consecutive edges may not fold back onto each other.
inline void check_subdomain_simple(const decomposition& d, std::size_t s,
                                   std::vector<std::string>& problems) {
  const subdomain& sd = d.subdomains[s];
  std::vector<std::pair<index_t, index_t>> edges;
  for (const auto& l : sd.loops)
    for (std::size_t i = 0; i < l.size(); ++i)
      edges.emplace_back(l[i], l[(i + 1) % l.size()]);
  std::vector<bbox> boxes;
  for (const auto& [u, w] : edges)
    boxes.push_back(segment_box(d.vertices[u], d.vertices[w]));
  std::size_t bad = 0;
  std::string first;
  for_each_box_pair(boxes, [&](std::size_t x, std::size_t y) {
    const auto [a, b] = edges[x];
    const auto [c, e] = edges[y];
    if (loop_edges_clash(d, a, b, c, e) && bad++ == 0)
      first = "edges (" + std::to_string(a) + ", " + std::to_string(b) + ") and (" +
              std::to_string(c) + ", " + std::to_string(e) + ")";
  });
  if (bad > 0)
    problems.push_back("subdomain " + std::to_string(s) + ": " + std::to_string(bad) +
                       " pairs of boundary edges intersect, e.g. " + first);
}

/// The points of g's vertices on four or more segments, sorted: the only points where a face of
/// g's domain can touch itself (a pinch vertex), so the only ones a subdomain may visit twice.
inline std::vector<point> pinch_candidates(const pslg& g) {
  std::vector<int> degree(g.vertices.size(), 0);
  for (const segment& sg : g.segments)
    ++degree[sg.a], ++degree[sg.b];
  std::vector<point> out;
  for (index_t v = 0; v < g.vertices.size(); ++v)
    if (degree[v] >= 4) out.push_back(g.vertices[v]);
  std::sort(out.begin(), out.end());
  return out;
}

/// Whether loop `l` (its points) runs counter-clockwise: CGAL's exact orientation at its
/// lowest-leftmost vertex; a loop that visits a pinch vertex twice (weakly simple, where that
/// vertex may be the extreme one) by the sign of its area.
inline bool loop_counter_clockwise(const std::vector<epick::Point_2>& l) {
  std::vector<epick::Point_2> sorted = l;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end())
    return CGAL::orientation_2(l.begin(), l.end(), epick()) == CGAL::COUNTERCLOCKWISE;
  return polygon_signed_area(l.size(), [&](std::size_t i) {
           return point{l[i].x(), l[i].y()};
         }) > 0.0;
}

/// A vertex of hole loop h of sd on no other loop of sd (no_index when every one is: a hole
/// that touches the others at all its vertices, which the nesting check then skips).
inline index_t own_vertex(const subdomain& sd, std::size_t h) {
  for (const index_t v : sd.loops[h]) {
    bool shared = false;
    for (std::size_t k = 0; k < sd.loops.size() && !shared; ++k)
      shared = k != h && std::find(sd.loops[k].begin(), sd.loops[k].end(), v) != sd.loops[k].end();
    if (!shared) return v;
  }
  return no_index;
}

/// Orientation and nesting of one subdomain's loops (each hole tested at a vertex of its own:
/// loops may touch at pinch vertices).
inline void check_subdomain_loops(const decomposition& d, std::size_t s,
                                  std::vector<std::string>& problems) {
  const subdomain& sd = d.subdomains[s];
  const std::string name = "subdomain " + std::to_string(s);
  std::vector<std::vector<epick::Point_2>> polys;
  for (const auto& l : sd.loops) {
    std::vector<epick::Point_2> p;
    for (const index_t v : l)
      p.emplace_back(d.vertices[v].x, d.vertices[v].y);
    polys.push_back(std::move(p));
  }
  for (std::size_t l = 0; l < polys.size(); ++l)
    if (loop_counter_clockwise(polys[l]) != (l == 0))
      problems.push_back(
          name + ": loop " + std::to_string(l) +
          (l == 0 ? " (outer) is not counter-clockwise" : " (hole) is not clockwise"));
  for (std::size_t h = 1; h < polys.size(); ++h) {
    const index_t own = own_vertex(sd, h);
    if (own == no_index) continue;
    const epick::Point_2 q(d.vertices[own].x, d.vertices[own].y);
    if (CGAL::bounded_side_2(polys[0].begin(), polys[0].end(), q, epick()) != CGAL::ON_BOUNDED_SIDE)
      problems.push_back(name + ": hole loop " + std::to_string(h) +
                         " is not inside the outer loop");
    for (std::size_t k = 1; k < polys.size(); ++k)
      if (k != h && CGAL::bounded_side_2(polys[k].begin(), polys[k].end(), q, epick()) !=
                        CGAL::ON_UNBOUNDED_SIDE)
        problems.push_back(name + ": hole loop " + std::to_string(h) + " lies inside hole loop " +
                           std::to_string(k));
  }
}

struct edge_occurrence {
  index_t s, from, to;
  edge_tag tag;
};
/// Every loop edge of a decomposition, by its endpoints (smaller id first).
using decomposition_edges = std::map<std::pair<index_t, index_t>, std::vector<edge_occurrence>>;

/// False (with the problem) when subdomain s has no loops, tags that do not match them, a loop
/// of fewer than 3 vertices or a vertex id out of range: nothing else can be checked then.
/// A vertex visited twice is a problem unless it lies at one of `pinches` (pinch_candidates).
inline bool check_subdomain_structure(const decomposition& d, std::size_t s,
                                      const std::vector<point>& pinches,
                                      std::vector<std::string>& pr) {
  const subdomain& sd = d.subdomains[s];
  const std::string name = "subdomain " + std::to_string(s);
  if (sd.loops.empty() || sd.tags.size() != sd.loops.size()) {
    pr.push_back(name + ": no loops, or tags do not match the loops");
    return false;
  }
  bool structure_ok = true;
  std::vector<index_t> all;
  for (std::size_t l = 0; l < sd.loops.size(); ++l) {
    const auto& loop = sd.loops[l];
    if (loop.size() < 3 || sd.tags[l].size() != loop.size()) structure_ok = false;
    for (const index_t v : loop) {
      if (v >= d.vertices.size()) structure_ok = false;
      all.push_back(v);
    }
  }
  if (!structure_ok) {
    pr.push_back(name + ": a loop has < 3 vertices, a vertex id out of range or wrong tags");
    return false;
  }
  std::sort(all.begin(), all.end());
  for (auto it = std::adjacent_find(all.begin(), all.end()); it != all.end();
       it = std::adjacent_find(it + 1, all.end()))
    if (!std::binary_search(pinches.begin(), pinches.end(), d.vertices[*it])) {
      pr.push_back(name + ": vertex " + std::to_string(*it) +
                   " occurs twice (the subdomain touches itself where the domain does not)");
      break;
    }
  return true;
}

/// Records the edges of subdomain s, checks its separator angles (Phi0) and its area field;
/// returns the area of its loops.
inline double check_subdomain_edges(const decomposition& d, std::size_t s,
                                    const decomposition_check_options& o, decomposition_report& rep,
                                    decomposition_edges& edges) {
  const subdomain& sd = d.subdomains[s];
  const std::string name = "subdomain " + std::to_string(s);
  auto& pr = rep.problems;
  double area = 0.0;
  for (std::size_t l = 0; l < sd.loops.size(); ++l) {
    const auto& loop = sd.loops[l];
    const std::size_t m = loop.size();
    std::vector<point> pts;
    for (std::size_t i = 0; i < m; ++i) {
      pts.push_back(d.vertices[loop[i]]);
      const index_t a = loop[i], b = loop[(i + 1) % m];
      const edge_tag& t = sd.tags[l][i];
      edges[{std::min(a, b), std::max(a, b)}].push_back({static_cast<index_t>(s), a, b, t});
      if (t.type != edge_tag::kind::interface &&
          sd.tags[l][(i + m - 1) % m].type != edge_tag::kind::interface)
        continue;
      const double ang =
          interior_angle_deg(d.vertices[loop[(i + m - 1) % m]], d.vertices[a], d.vertices[b]);
      rep.min_separator_angle_deg = std::min(rep.min_separator_angle_deg, ang);
      if (ang < o.min_angle_deg - o.angle_tolerance_deg && pr.size() < o.max_problems)
        pr.push_back(name + ": separator angle " + std::to_string(ang) + " deg at vertex " +
                     std::to_string(a) + " is below " + std::to_string(o.min_angle_deg));
    }
    area += polygon_signed_area(pts);
  }
  if (std::abs(area - sd.area) > 1e-12 * std::max(1.0, std::abs(area)) + 1e-9 * std::abs(area))
    pr.push_back(name + ": area field " + std::to_string(sd.area) + " differs from its loops' " +
                 std::to_string(area));
  return area;
}

/// True when p lies farther than 1e-9 |ab| from the line through the input segment ab (split
/// points are rounded, so a piece's ends lie on its segment only up to rounding).
inline bool off_segment(point a, point b, point p) noexcept {
  const double len = distance(a, b);
  return std::abs((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / len > 1e-9 * len;
}

/// An external edge: in one subdomain, on the input segment it names, with its marker; adds
/// its length to `covered`.
inline void check_external_edge(const std::pair<index_t, index_t>& key,
                                const std::vector<edge_occurrence>& list, const decomposition& d,
                                const pslg& g, std::vector<double>& covered,
                                std::vector<std::string>& pr) {
  const std::string ename =
      "edge (" + std::to_string(key.first) + ", " + std::to_string(key.second) + ")";
  const edge_occurrence& x = list[0];
  if (list.size() != 1) {
    pr.push_back(ename + " is external but occurs " + std::to_string(list.size()) + " times");
    return;
  }
  if (x.tag.id >= g.segments.size()) {
    pr.push_back(ename + " names input segment " + std::to_string(x.tag.id) +
                 ", which does not exist");
    return;
  }
  const segment& sg = g.segments[x.tag.id];
  const point a = g.vertices[sg.a], b = g.vertices[sg.b];
  if (off_segment(a, b, d.vertices[key.first]) || off_segment(a, b, d.vertices[key.second]))
    pr.push_back(ename + " does not lie on input segment " + std::to_string(x.tag.id));
  if (x.tag.marker != sg.marker)
    pr.push_back(ename + " has marker " + std::to_string(x.tag.marker) + ", its segment " +
                 std::to_string(sg.marker));
  covered[x.tag.id] += distance(d.vertices[key.first], d.vertices[key.second]);
}

/// An interface edge: in exactly two subdomains, in opposite directions, with the same
/// interface id, each other as neighbour, and an existing interface between the two.
inline void check_interface_edge(const std::pair<index_t, index_t>& key,
                                 const std::vector<edge_occurrence>& list, const decomposition& d,
                                 std::vector<std::string>& pr) {
  const std::string ename =
      "edge (" + std::to_string(key.first) + ", " + std::to_string(key.second) + ")";
  if (list.size() != 2) {
    pr.push_back(ename + " is an interface edge in " + std::to_string(list.size()) +
                 " subdomains (must be 2)");
    return;
  }
  const edge_occurrence &x = list[0], &y = list[1];
  if (y.tag.type != edge_tag::kind::interface || x.s == y.s || x.from != y.to ||
      x.tag.id != y.tag.id || x.tag.neighbour != y.s || y.tag.neighbour != x.s)
    pr.push_back(ename + ": its two sides (subdomains " + std::to_string(x.s) + ", " +
                 std::to_string(y.s) + ") do not match (direction, interface id, neighbour)");
  else if (x.tag.id >= d.interfaces.size() || d.interfaces[x.tag.id].a != std::min(x.s, y.s) ||
           d.interfaces[x.tag.id].b != std::max(x.s, y.s))
    pr.push_back(ename + ": interface " + std::to_string(x.tag.id) +
                 " does not exist or joins other subdomains");
}

/// The vertices of subdomain sd's separator edges (interface edges not on an input segment).
inline std::vector<index_t> separator_vertices(const subdomain& sd) {
  std::vector<index_t> out;
  for (std::size_t l = 0; l < sd.loops.size() && l < sd.tags.size(); ++l)
    for (std::size_t i = 0; i < sd.loops[l].size() && i < sd.tags[l].size(); ++i) {
      const edge_tag& t = sd.tags[l][i];
      if (t.type != edge_tag::kind::interface || t.on_segment) continue;
      out.push_back(sd.loops[l][i]);
      out.push_back(sd.loops[l][(i + 1) % sd.loops[l].size()]);
    }
  std::sort(out.begin(), out.end());
  return out;
}

/// Inner constraints (general PSLGs): ids in range, each segment on the input segment it
/// names (the whole segment, or inside a cap a piece of it from its end; same marker; adds
/// its length to `covered`), and no end of an input segment on a separator of its subdomain
/// (no separator touches them; a separator of a neighbouring face may end at a vertex they
/// share on the segment between the two faces; a cap's chords meet its pieces where they are
/// cut, at >= 65 deg).
inline void check_inner_constraints(const decomposition& d, const pslg& g,
                                    std::vector<double>& covered, std::size_t max_problems,
                                    std::vector<std::string>& pr) {
  for (std::size_t s = 0; s < d.subdomains.size() && pr.size() < max_problems; ++s) {
    const std::vector<index_t> separator = separator_vertices(d.subdomains[s]);
    const auto on_interface = [&](index_t v) {
      return std::binary_search(separator.begin(), separator.end(), v);
    };
    for (const inner_constraint& c : d.subdomains[s].inner) {
      const std::string at = "inner constraint of subdomain " + std::to_string(s);
      if (c.a >= d.vertices.size() || c.b >= d.vertices.size()) {
        pr.push_back(at + ": vertex id out of range");
        continue;
      }
      if (c.segment == no_index) {
        if (on_interface(c.a))
          pr.push_back(at + " touches a separator at vertex " + std::to_string(c.a));
        continue;
      }
      if (c.segment >= g.segments.size()) {
        pr.push_back(at + ": segment id out of range");
        continue;
      }
      const segment& sg = g.segments[c.segment];
      const point pa = g.vertices[sg.a], pb = g.vertices[sg.b];
      const point qa = d.vertices[c.a], qb = d.vertices[c.b];
      const auto input_end = [&](point q) { return q == pa || q == pb; };
      for (const index_t v : {c.a, c.b})
        if (on_interface(v) && input_end(d.vertices[v]))
          pr.push_back(at + " touches a separator at vertex " + std::to_string(v));
      if (!(input_end(qa) || input_end(qb)) || off_segment(pa, pb, qa) || off_segment(pa, pb, qb) ||
          c.marker != sg.marker)
        pr.push_back(at + " is not (a piece from an end of) input segment " +
                     std::to_string(c.segment));
      else
        covered[c.segment] += distance(qa, qb);
    }
  }
}

/// The external edges and inner constraints cover every input segment exactly (relative
/// 1e-9), except, by Triangle's rule, the segments with no domain face beside them (not
/// meshed) and those between two faces of a general PSLG: what of the latter they leave
/// uncovered (all of it, or all but the pieces inside caps) must add up to the length of the
/// interface edges on input segments (edge_tag::on_segment), which do not name their segment.
inline void check_segment_coverage(const pslg& g, const std::vector<double>& covered,
                                   double on_segment_length, std::size_t max_problems,
                                   std::vector<std::string>& pr) {
  std::vector<char> meshed(g.segments.size(), 1); // by Triangle's rule: a domain face beside it
  if (g.rule == domain_rule::triangle) {
    const domain_faces faces(g);
    for (std::size_t sg = 0; sg < g.segments.size(); ++sg)
      meshed[sg] = faces.touches_domain(g.segments[sg].a, g.segments[sg].b) ? 1 : 0;
  }
  double uncovered = 0.0;
  for (std::size_t sg = 0; sg < g.segments.size() && pr.size() < max_problems; ++sg) {
    const double len = distance(g.vertices[g.segments[sg].a], g.vertices[g.segments[sg].b]);
    if (!meshed[sg] && covered[sg] == 0.0) continue; // dangling outside the domain: not meshed
    if (covered[sg] < len * (1.0 - 1e-9) && on_segment_length > 0.0)
      uncovered += len - covered[sg];
    else if (std::abs(covered[sg] - len) > 1e-9 * len)
      pr.push_back("input segment " + std::to_string(sg) + " is covered to length " +
                   std::to_string(covered[sg]) + " of " + std::to_string(len));
  }
  if (std::abs(uncovered - on_segment_length) > 1e-9 * std::max(uncovered, on_segment_length))
    pr.push_back("the input segments no external edge covers have length " +
                 std::to_string(uncovered) + ", the interface edges on input segments " +
                 std::to_string(on_segment_length));
}

/// Interface curves: each consecutive pair is an edge of that interface, and the curves have
/// as many edges as the subdomains' interface edges.
inline void check_interface_curves(const decomposition& d, const decomposition_edges& edges,
                                   std::size_t max_problems, std::vector<std::string>& pr) {
  std::size_t curve_edges = 0, interface_edges = 0;
  for (const auto& [key, list] : edges)
    if (list[0].tag.type == edge_tag::kind::interface) ++interface_edges;
  for (std::size_t c = 0; c < d.interfaces.size() && pr.size() < max_problems; ++c) {
    const interface_curve& ic = d.interfaces[c];
    if (ic.a >= ic.b || ic.vertices.size() < 2)
      pr.push_back("interface " + std::to_string(c) + " has a >= b or fewer than two vertices");
    for (std::size_t k = 0; k + 1 < ic.vertices.size(); ++k) {
      ++curve_edges;
      const auto key = std::make_pair(std::min(ic.vertices[k], ic.vertices[k + 1]),
                                      std::max(ic.vertices[k], ic.vertices[k + 1]));
      const auto it = edges.find(key);
      if (it == edges.end() || it->second[0].tag.type != edge_tag::kind::interface ||
          it->second[0].tag.id != c) {
        pr.push_back("interface " + std::to_string(c) + ": (" + std::to_string(key.first) + ", " +
                     std::to_string(key.second) + ") is not one of its edges");
        break;
      }
    }
  }
  if (curve_edges != interface_edges && pr.size() < max_problems)
    pr.push_back("the interface curves have " + std::to_string(curve_edges) + " edges, the " +
                 "subdomains " + std::to_string(interface_edges));
}

} // namespace pdd::detail
