// Decompositions built by hand for the decoupling tests (until and besides MADD): a rectangle
// cut by straight separators into an nx x ny grid, and an annulus cut into four quarters.
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/core/pslg.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

namespace pdd::test {

/// A domain and a decomposition of it.
struct hand_case {
  pslg domain;
  decomposition parts;
};

/// The rectangle [0, w] x [0, h] (segments 0..3: bottom, right, top, left with markers 1..4)
/// cut into nx x ny equal cells by straight separators. Subdomain i + nx * j is cell (i, j).
inline hand_case grid_case(int nx, int ny, double w = 1.0, double h = 1.0) {
  hand_case c;
  c.domain.add_loop(std::vector<point>{{0, 0}, {w, 0}, {w, h}, {0, h}}, 0);
  for (int s = 0; s < 4; ++s)
    c.domain.segments[s].marker = s + 1;
  decomposition& d = c.parts;
  const auto vid = [&](int i, int j) { return static_cast<index_t>(i + (nx + 1) * j); };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      d.vertices.push_back({w * i / nx, h * j / ny});
      const bool corner = (i == 0 || i == nx) && (j == 0 || j == ny);
      d.vertex_markers.push_back(corner ? 1
                                        : (j == 0    ? 1
                                           : i == nx ? 2
                                           : j == ny ? 3
                                           : i == 0  ? 4
                                                     : 0));
    }
  std::map<std::pair<index_t, index_t>, index_t> iface_id;
  const auto sub = [&](int i, int j) { return static_cast<index_t>(i + nx * j); };
  const auto interface_of = [&](index_t s, index_t t, index_t a, index_t b) {
    const auto key = std::minmax(s, t);
    auto it = iface_id.find(key);
    if (it == iface_id.end()) {
      it = iface_id.emplace(key, static_cast<index_t>(d.interfaces.size())).first;
      interface_curve ic{key.first, key.second, {}};
      ic.vertices =
          d.vertices[a] < d.vertices[b] ? std::vector<index_t>{a, b} : std::vector<index_t>{b, a};
      d.interfaces.push_back(ic);
    }
    return it->second;
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      subdomain sd;
      const std::vector<index_t> loop{vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)};
      std::vector<edge_tag> tags(4);
      const index_t s = sub(i, j);
      // bottom, right, top, left
      const bool ext[4] = {j == 0, i == nx - 1, j == ny - 1, i == 0};
      const int nbi[4] = {i, i + 1, i, i - 1};
      const int nbj[4] = {j - 1, j, j + 1, j};
      for (int e = 0; e < 4; ++e) {
        if (ext[e]) {
          tags[e] = {edge_tag::kind::external, static_cast<index_t>(e), e + 1, no_index};
        } else {
          const index_t t = sub(nbi[e], nbj[e]);
          tags[e] = {edge_tag::kind::interface, interface_of(s, t, loop[e], loop[(e + 1) % 4]), 0,
                     t};
        }
      }
      sd.loops.push_back(loop);
      sd.tags.push_back(tags);
      sd.area = (w / nx) * (h / ny);
      d.subdomains.push_back(sd);
    }
  return c;
}

/// The annulus between a regular 32-gon of radius 1 (segments 0..31, marker 1) and a 16-gon of
/// radius 0.5 (segments 32..47, marker 2, hole point at the origin), cut by four radial
/// separators at 0, 90, 180 and 270 degrees into quarters (subdomain q spans [90q, 90q + 90]).
inline hand_case annulus_case() {
  hand_case c;
  constexpr int no = 32, ni = 16;
  std::vector<point> outer, inner;
  for (int i = 0; i < no; ++i) {
    const double t = 2 * std::numbers::pi * i / no;
    outer.push_back({std::cos(t), std::sin(t)});
  }
  for (int i = 0; i < ni; ++i) {
    const double t = 2 * std::numbers::pi * i / ni;
    inner.push_back({0.5 * std::cos(t), 0.5 * std::sin(t)});
  }
  c.domain.add_loop(outer, 1);
  // The hole loop is clockwise.
  std::vector<point> inner_cw(inner.rbegin(), inner.rend());
  c.domain.add_loop(inner_cw, 2);
  c.domain.holes.push_back({0, 0});
  decomposition& d = c.parts;
  for (const point& p : outer) {
    d.vertices.push_back(p);
    d.vertex_markers.push_back(1);
  }
  for (const point& p : inner) {
    d.vertices.push_back(p);
    d.vertex_markers.push_back(2);
  }
  // Input segment ids: outer edge i -> i + 1 is segment i; the inner loop was added clockwise,
  // so the inner edge between inner[i] and inner[i + 1] is segment 32 + (ni - 2 - i) mod ni.
  const auto inner_segment = [&](int i) {
    return static_cast<index_t>(no + ((ni - 2 - i + ni) % ni));
  };
  for (int q = 0; q < 4; ++q) {
    subdomain sd;
    std::vector<index_t> loop;
    std::vector<edge_tag> tags;
    const int o0 = q * no / 4, i0 = q * ni / 4;
    for (int k = 0; k <= no / 4; ++k) {
      loop.push_back(static_cast<index_t>((o0 + k) % no));
      if (k < no / 4)
        tags.push_back(
            {edge_tag::kind::external, static_cast<index_t>((o0 + k) % no), 1, no_index});
    }
    // outer(theta1) -> inner(theta1): interface with quarter q + 1 (id: separator at theta1).
    tags.push_back({edge_tag::kind::interface, static_cast<index_t>((q + 1) % 4), 0,
                    static_cast<index_t>((q + 1) % 4)});
    for (int k = ni / 4; k >= 0; --k) {
      loop.push_back(static_cast<index_t>(no + (i0 + k) % ni));
      if (k > 0)
        tags.push_back({edge_tag::kind::external, inner_segment((i0 + k - 1) % ni), 2, no_index});
    }
    // inner(theta0) -> outer(theta0): interface with quarter q - 1 (separator at theta0).
    tags.push_back(
        {edge_tag::kind::interface, static_cast<index_t>(q), 0, static_cast<index_t>((q + 3) % 4)});
    sd.loops.push_back(loop);
    sd.tags.push_back(tags);
    double twice = 0; // shoelace: the loop is counter-clockwise
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const point p = d.vertices[loop[k]], r = d.vertices[loop[(k + 1) % loop.size()]];
      twice += p.x * r.y - r.x * p.y;
    }
    sd.area = 0.5 * twice;
    d.subdomains.push_back(sd);
  }
  for (int q = 0; q < 4; ++q) {
    const index_t a = static_cast<index_t>((q * no / 4) % no),
                  b = static_cast<index_t>(no + (q * ni / 4) % ni);
    interface_curve ic{static_cast<index_t>(std::min((q + 3) % 4, q)),
                       static_cast<index_t>(std::max((q + 3) % 4, q)),
                       {}};
    ic.vertices =
        d.vertices[a] < d.vertices[b] ? std::vector<index_t>{a, b} : std::vector<index_t>{b, a};
    d.interfaces.push_back(ic);
  }
  return c;
}

} // namespace pdd::test
