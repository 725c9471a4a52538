/// \file validate_decomposition.hpp
/// pdd::validate_decomposition: checks that a decomposition is a conforming partition of its
/// domain into polygons with holes with separator angles >= Phi0 (the guarantees of MADD,
/// dissertation ch. 3; used by the tests and by the pdd-decompose driver).
#pragma once

#include <pdd/core/kernel.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/madd/decomposition.hpp>
#include <pdd/madd/detail/region.hpp>

#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace pdd {

/// What validate_decomposition checks against.
struct decomposition_check_options {
  double min_angle_deg = 60.0;       ///< Phi0
  double angle_tolerance_deg = 1e-9; ///< angles >= Phi0 - tolerance pass
  double area_tolerance = 1e-9;      ///< relative, for the sum of the areas
  std::size_t max_problems = 50;     ///< stop listing after this many
};

/// The findings of validate_decomposition.
struct decomposition_report {
  std::vector<std::string> problems;
  double domain_area = 0.0;
  double area_sum = 0.0;
  double min_separator_angle_deg = 180.0;
  bool ok() const noexcept { return problems.empty(); }
  /// The problems, one per line ("ok" when there are none).
  std::string summary() const {
    if (problems.empty()) return "ok";
    std::string s;
    for (const auto& p : problems)
      s += p + "\n";
    return s;
  }
  /// \throws decomposition_error with the summary unless ok().
  void throw_if_invalid() const {
    if (!ok()) throw decomposition_error("invalid decomposition:\n" + summary());
  }
};

namespace detail {

/// Segment intersections inside one subdomain (all its loops together): two edges may only
/// share an endpoint, and consecutive edges may not fold back onto each other.
inline void check_subdomain_simple(const decomposition& d, std::size_t s,
                                   std::vector<std::string>& problems) {
  using box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;
  const subdomain& sd = d.subdomains[s];
  std::vector<std::pair<index_t, index_t>> edges;
  for (const auto& l : sd.loops)
    for (std::size_t i = 0; i < l.size(); ++i)
      edges.emplace_back(l[i], l[(i + 1) % l.size()]);
  std::vector<box> boxes;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const point a = d.vertices[edges[e].first], b = d.vertices[edges[e].second];
    double lo[2] = {std::min(a.x, b.x), std::min(a.y, b.y)};
    double hi[2] = {std::max(a.x, b.x), std::max(a.y, b.y)};
    boxes.emplace_back(lo, hi, e);
  }
  std::size_t bad = 0;
  std::string first;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const box& x, const box& y) {
    const auto [a, b] = edges[x.info()];
    const auto [c, e] = edges[y.info()];
    const epick::Point_2 pa(d.vertices[a].x, d.vertices[a].y), pb(d.vertices[b].x, d.vertices[b].y);
    const epick::Point_2 pc(d.vertices[c].x, d.vertices[c].y), pe(d.vertices[e].x, d.vertices[e].y);
    bool wrong = false;
    const int shared = (a == c) + (a == e) + (b == c) + (b == e);
    if (shared >= 2) {
      wrong = true; // the same edge twice
    } else if (shared == 1) {
      const index_t v = (a == c || a == e) ? a : b;
      const epick::Point_2 pv(d.vertices[v].x, d.vertices[v].y);
      const epick::Point_2& p = v == a ? pb : pa;
      const epick::Point_2& q = (v == c) ? pe : pc;
      wrong = CGAL::collinear(pv, p, q) && CGAL::angle(p, pv, q) == CGAL::ACUTE;
    } else {
      wrong = CGAL::do_intersect(epick::Segment_2(pa, pb), epick::Segment_2(pc, pe));
    }
    if (wrong && bad++ == 0)
      first = "edges (" + std::to_string(a) + ", " + std::to_string(b) + ") and (" +
              std::to_string(c) + ", " + std::to_string(e) + ")";
  });
  if (bad > 0)
    problems.push_back("subdomain " + std::to_string(s) + ": " + std::to_string(bad) +
                       " pairs of boundary edges intersect, e.g. " + first);
}

/// Orientation and nesting of one subdomain's loops.
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
  for (std::size_t l = 0; l < polys.size(); ++l) {
    const auto o = CGAL::orientation_2(polys[l].begin(), polys[l].end(), epick());
    if (o != (l == 0 ? CGAL::COUNTERCLOCKWISE : CGAL::CLOCKWISE))
      problems.push_back(
          name + ": loop " + std::to_string(l) +
          (l == 0 ? " (outer) is not counter-clockwise" : " (hole) is not clockwise"));
  }
  for (std::size_t h = 1; h < polys.size(); ++h) {
    const auto& q = polys[h][0];
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

} // namespace detail

/// Checks a decomposition of the domain of g: every subdomain is a polygon with holes (outer
/// loop counter-clockwise, holes clockwise and inside it, no vertex twice, no two edges
/// crossing or overlapping); its area field matches its loops; the areas add up to the
/// domain's area (relative tolerance); every external edge lies on the input segment it names
/// (same marker) exactly once and the external edges cover every input segment; every
/// interface edge is in exactly two subdomains, in opposite directions, with the same
/// interface id and each other as neighbour, and lies on its interface curve; every interior
/// angle of a subdomain at a vertex with an incident interface edge is >= Phi0 - tolerance.
/// Returns every problem found (up to max_problems), never throws for a bad decomposition.
/// \throws geometry_error if g itself has no valid loops (find_loops).
/// Complexity O(n log n) for n loop edges. Thread-safe.
inline decomposition_report validate_decomposition(const decomposition& d, const pslg& g,
                                                   const decomposition_check_options& o = {}) {
  decomposition_report rep;
  auto& pr = rep.problems;
  const std::size_t nv = d.vertices.size();
  if (d.vertex_markers.size() != nv) pr.push_back("vertex_markers has the wrong size");
  std::vector<double> covered(g.segments.size(), 0.0);
  struct occ {
    index_t s, from, to;
    edge_tag tag;
  };
  std::map<std::pair<index_t, index_t>, std::vector<occ>> edges;
  for (std::size_t s = 0; s < d.subdomains.size() && pr.size() < o.max_problems; ++s) {
    const subdomain& sd = d.subdomains[s];
    const std::string name = "subdomain " + std::to_string(s);
    if (sd.loops.empty() || sd.tags.size() != sd.loops.size()) {
      pr.push_back(name + ": no loops, or tags do not match the loops");
      continue;
    }
    bool structure_ok = true;
    std::vector<index_t> all;
    for (std::size_t l = 0; l < sd.loops.size(); ++l) {
      const auto& loop = sd.loops[l];
      if (loop.size() < 3 || sd.tags[l].size() != loop.size()) structure_ok = false;
      for (const index_t v : loop) {
        if (v >= nv) structure_ok = false;
        all.push_back(v);
      }
    }
    if (!structure_ok) {
      pr.push_back(name + ": a loop has < 3 vertices, a vertex id out of range or wrong tags");
      continue;
    }
    std::sort(all.begin(), all.end());
    if (std::adjacent_find(all.begin(), all.end()) != all.end())
      pr.push_back(name + ": vertex " +
                   std::to_string(*std::adjacent_find(all.begin(), all.end())) +
                   " occurs twice (the subdomain touches itself)");
    detail::check_subdomain_loops(d, s, pr);
    detail::check_subdomain_simple(d, s, pr);
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
        const bool touches_interface =
            t.type == edge_tag::kind::interface ||
            sd.tags[l][(i + m - 1) % m].type == edge_tag::kind::interface;
        if (touches_interface) {
          const double ang = detail::interior_angle_deg(d.vertices[loop[(i + m - 1) % m]],
                                                        d.vertices[a], d.vertices[b]);
          rep.min_separator_angle_deg = std::min(rep.min_separator_angle_deg, ang);
          if (ang < o.min_angle_deg - o.angle_tolerance_deg && pr.size() < o.max_problems)
            pr.push_back(name + ": separator angle " + std::to_string(ang) + " deg at vertex " +
                         std::to_string(a) + " is below " + std::to_string(o.min_angle_deg));
        }
      }
      area += detail::signed_area(pts);
    }
    if (std::abs(area - sd.area) > 1e-12 * std::max(1.0, std::abs(area)) + 1e-9 * std::abs(area))
      pr.push_back(name + ": area field " + std::to_string(sd.area) + " differs from its loops' " +
                   std::to_string(area));
    rep.area_sum += area;
  }
  // Edges: external once on their segment, interfaces twice with matching tags.
  for (const auto& [key, list] : edges) {
    if (pr.size() >= o.max_problems) break;
    const std::string ename =
        "edge (" + std::to_string(key.first) + ", " + std::to_string(key.second) + ")";
    const occ& x = list[0];
    if (x.tag.type == edge_tag::kind::external) {
      if (list.size() != 1) {
        pr.push_back(ename + " is external but occurs " + std::to_string(list.size()) + " times");
        continue;
      }
      if (x.tag.id >= g.segments.size()) {
        pr.push_back(ename + " names input segment " + std::to_string(x.tag.id) +
                     ", which does not exist");
        continue;
      }
      const segment& sg = g.segments[x.tag.id];
      const point a = g.vertices[sg.a], b = g.vertices[sg.b];
      const double len = detail::distance(a, b);
      auto off = [&](point p) {
        return std::abs((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / len;
      };
      if (off(d.vertices[key.first]) > 1e-9 * len || off(d.vertices[key.second]) > 1e-9 * len)
        pr.push_back(ename + " does not lie on input segment " + std::to_string(x.tag.id));
      if (x.tag.marker != sg.marker)
        pr.push_back(ename + " has marker " + std::to_string(x.tag.marker) + ", its segment " +
                     std::to_string(sg.marker));
      covered[x.tag.id] += detail::distance(d.vertices[key.first], d.vertices[key.second]);
      continue;
    }
    if (list.size() != 2) {
      pr.push_back(ename + " is an interface edge in " + std::to_string(list.size()) +
                   " subdomains (must be 2)");
      continue;
    }
    const occ& y = list[1];
    if (y.tag.type != edge_tag::kind::interface || x.s == y.s || x.from != y.to ||
        x.tag.id != y.tag.id || x.tag.neighbour != y.s || y.tag.neighbour != x.s)
      pr.push_back(ename + ": its two sides (subdomains " + std::to_string(x.s) + ", " +
                   std::to_string(y.s) + ") do not match (direction, interface id, neighbour)");
    else if (x.tag.id >= d.interfaces.size() || d.interfaces[x.tag.id].a != std::min(x.s, y.s) ||
             d.interfaces[x.tag.id].b != std::max(x.s, y.s))
      pr.push_back(ename + ": interface " + std::to_string(x.tag.id) +
                   " does not exist or joins other subdomains");
  }
  for (std::size_t sg = 0; sg < g.segments.size() && pr.size() < o.max_problems; ++sg) {
    const double len = detail::distance(g.vertices[g.segments[sg].a], g.vertices[g.segments[sg].b]);
    if (std::abs(covered[sg] - len) > 1e-9 * len)
      pr.push_back("input segment " + std::to_string(sg) + " is covered to length " +
                   std::to_string(covered[sg]) + " of " + std::to_string(len));
  }
  // Interface curves: each consecutive pair is an edge of that interface.
  std::size_t curve_edges = 0, interface_edges = 0;
  for (const auto& [key, list] : edges)
    if (list[0].tag.type == edge_tag::kind::interface) ++interface_edges;
  for (std::size_t c = 0; c < d.interfaces.size() && pr.size() < o.max_problems; ++c) {
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
  if (curve_edges != interface_edges && pr.size() < o.max_problems)
    pr.push_back("the interface curves have " + std::to_string(curve_edges) + " edges, the " +
                 "subdomains " + std::to_string(interface_edges));
  rep.domain_area = domain_area(g);
  if (std::abs(rep.area_sum - rep.domain_area) > o.area_tolerance * std::abs(rep.domain_area))
    pr.push_back("the subdomain areas add up to " + std::to_string(rep.area_sum) +
                 ", the domain's area is " + std::to_string(rep.domain_area));
  return rep;
}

} // namespace pdd
