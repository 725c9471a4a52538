/// \file graded_options.hpp
/// The graded MADD (dissertation 4.4) of a pdd-decompose run from its options: density
/// weights (--vertex-weights, --node-weights, --grid-weights with --uniform-factor,
/// --weight-factor, --interpolation) or required subdomain areas (--area-function,
/// --area-mesh, --area-grid with --area-ratio); and their statistics for --stats.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/io/area_grid.hpp>
#include <pdd/io/background_mesh.hpp>
#include <pdd/io/weight_files.hpp>
#include <pdd/madd/graded_weights.hpp>
#include <pdd/madd/madd_options.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/expression.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pdd::drivers {

/// The graded options as given on the command line (empty strings: not given).
struct graded_sources {
  bool vertex_weights = false;
  std::string node_weights, grid_weights;          ///< density-weight files
  std::string area_function, area_mesh, area_grid; ///< required subdomain area
  pdd::graded_madd_options factors;                ///< u, a, p
  double area_ratio = 1.0;                         ///< the bound on area / required area
  bool density() const { return vertex_weights || !node_weights.empty() || !grid_weights.empty(); }
  bool area() const { return !area_function.empty() || !area_mesh.empty() || !area_grid.empty(); }
};

/// Adds the graded options to a CLI11 app; at most one weight source and one area source,
/// not both kinds at once.
inline void add_graded_options(CLI::App& app, graded_sources& g) {
  auto* vw = app.add_flag("--vertex-weights", g.vertex_weights,
                          "graded MADD (4.4): density weights from the .poly's first vertex "
                          "attribute, interpolated onto the interfaces (see --interpolation)");
  auto* nw = app.add_option("--node-weights", g.node_weights,
                            "graded MADD: density weights of points, a .node file with the "
                            "weight as its one vertex attribute");
  auto* gw = app.add_option("--grid-weights", g.grid_weights,
                            "graded MADD: density weights on a grid (area grid format, values "
                            ">= 0)");
  auto* af = app.add_option("--area-function", g.area_function,
                            "graded MADD: required subdomain area, an expression of x and y");
  auto* am = app.add_option("--area-mesh", g.area_mesh,
                            "graded MADD: required subdomain area on a background mesh "
                            "(FILE.node + .ele, area per vertex or a .area file)");
  auto* ag = app.add_option("--area-grid", g.area_grid,
                            "graded MADD: required subdomain area on a grid (area grid file)");
  for (CLI::Option* a : {vw, nw, gw, af, am, ag})
    for (CLI::Option* b : {vw, nw, gw, af, am, ag})
      if (a != b) a->excludes(b);
  app.add_option("--uniform-factor", g.factors.uniform_factor,
                 "u: weight of a subdomain's area in u*area + a*weight (default 3)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--weight-factor", g.factors.weight_factor,
                 "a: weight of a subdomain's density weight (default 3)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--interpolation", g.factors.interpolation,
                 "p: scale of the boundary weights interpolated onto interfaces, in [0, 1] "
                 "(default 0.5; 0: interfaces weigh 0)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--area-ratio", g.area_ratio,
                 "split until no subdomain's area / required area exceeds this (default 1)")
      ->check(CLI::PositiveNumber);
}

/// The required-area field of the area sources (call only when g.area()).
inline pdd::any_sizing required_area_field(const graded_sources& g) {
  if (!g.area_function.empty()) return pdd::any_sizing(pdd::expression_sizing(g.area_function));
  if (!g.area_mesh.empty()) return pdd::any_sizing(pdd::read_background_mesh(g.area_mesh));
  return pdd::any_sizing(pdd::read_area_grid(g.area_grid));
}

/// The density weights of the weight sources (call only when g.density()).
inline std::function<std::vector<double>(std::span<const pdd::madd_leaf_view>)>
density_weights(const graded_sources& g, const pdd::pslg& domain) {
  if (g.vertex_weights)
    return pdd::boundary_vertex_weights(domain, pdd::first_vertex_attribute(domain),
                                        g.factors.interpolation);
  if (!g.node_weights.empty()) return pdd::read_node_weights(g.node_weights);
  return pdd::read_weight_grid(g.grid_weights);
}

/// What a graded run needs after MADD: the weights or the required areas of the leaves.
struct graded_run {
  std::function<std::vector<double>(std::span<const pdd::madd_leaf_view>)> weights;
  std::optional<pdd::any_sizing> required_area;
};

/// Sets o.split_policy from the sources (nothing when no graded option is given).
/// \throws pdd::error (file:line for files) for bad files, expressions or factors.
inline graded_run set_split_policy(const graded_sources& g, const pdd::pslg& domain,
                                   pdd::madd_options& o) {
  graded_run r;
  if (g.density()) {
    r.weights = density_weights(g, domain);
    o.split_policy = pdd::density_weight_policy(r.weights, g.factors);
  } else if (g.area()) {
    r.required_area = required_area_field(g);
    o.split_policy = pdd::area_ratio_policy(*r.required_area, g.area_ratio);
  }
  return r;
}

/// The "graded" object of --stats: the mode, the factors, and per subdomain the density
/// weights and priorities (min/max) or the area ratios (max, and the bound).
inline nlohmann::json graded_json(const graded_sources& g, const graded_run& r,
                                  const pdd::decomposition& d) {
  const pdd::decomposition_leaves leaves = pdd::leaves_of(d);
  nlohmann::json j;
  const auto min_max = [](const std::vector<double>& v) {
    return v.empty() ? std::vector<double>{0.0, 0.0}
                     : std::vector<double>{*std::min_element(v.begin(), v.end()),
                                           *std::max_element(v.begin(), v.end())};
  };
  if (r.weights) {
    const std::vector<double> w = r.weights(leaves.views);
    std::vector<double> prio(w.size());
    for (std::size_t i = 0; i < w.size(); ++i)
      prio[i] = g.factors.uniform_factor * leaves.views[i].area + g.factors.weight_factor * w[i];
    j["mode"] = g.vertex_weights          ? "vertex_weights"
                : !g.node_weights.empty() ? "node_weights"
                                          : "grid_weights";
    j["uniform_factor"] = g.factors.uniform_factor;
    j["weight_factor"] = g.factors.weight_factor;
    j["interpolation"] = g.factors.interpolation;
    j["weight_min"] = min_max(w)[0];
    j["weight_max"] = min_max(w)[1];
    j["priority_min"] = min_max(prio)[0];
    j["priority_max"] = min_max(prio)[1];
  } else {
    const std::vector<double> req = pdd::required_areas(*r.required_area, leaves.views);
    std::vector<double> ratio(req.size());
    for (std::size_t i = 0; i < req.size(); ++i)
      ratio[i] = leaves.views[i].area / req[i];
    j["mode"] = "area_ratio";
    j["area_ratio_bound"] = g.area_ratio;
    j["area_ratio_min"] = min_max(ratio)[0];
    j["area_ratio_max"] = min_max(ratio)[1];
  }
  return j;
}

} // namespace pdd::drivers
