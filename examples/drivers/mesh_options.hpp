/// \file mesh_options.hpp
/// The options pdd-mesh and pdd-mesh-mpi share (the input, the quality and sizing criteria, N,
/// threads, --max-triangles, the per-subdomain output, --stats, --quiet), registered once for both,
/// and the generate_options they give.
#pragma once

#include "sizing_options.hpp"

#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/madd/gradation_options.hpp>
#include <pdd/pipeline/options.hpp>

#include <CLI/CLI.hpp>

#include <cstddef>
#include <limits>
#include <string>

namespace pdd::drivers {

/// The values of the shared options.
struct mesh_options {
  std::string input, per_subdomain_dir, stats;
  sizing_sources sizing; // --sizing, --background, --area-grid
  double min_angle = pdd::mesh_criteria{}.min_angle_deg;
  double max_area = std::numeric_limits<double>::infinity();
  std::size_t subdomains = 0;
  std::size_t max_triangles = 0; ///< 0: what fits in memory
  unsigned threads = 0;
  pdd::gradation_options gradation;      // --r1, --r2 (Algorithm 7.1 of the graded method)
  std::string geometric_sizing = "auto"; // --geometric-sizing (Algorithm 8.3)
  bool quiet = false;
};

/// Registers the shared options on `app` (`threads_help` describes --threads) and returns the
/// --output-per-subdomain option (pdd-mesh excludes other outputs with it).
inline CLI::Option* add_mesh_options(CLI::App& app, mesh_options& o,
                                     const std::string& threads_help) {
  app.add_option("input", o.input, "input domain (Triangle .poly)")->required();
  app.add_option("--min-angle", o.min_angle, "minimum angle in degrees (default 20.7)")
      ->check(CLI::Range(1.0, 34.0));
  app.add_option("--max-area", o.max_area, "maximum triangle area")->check(CLI::PositiveNumber);
  app.add_option("--sizing", o.sizing.expression,
                 "maximum triangle area as an expression of x and y (muParser), e.g. "
                 "\"1e-4*(1+10*x^2)\"");
  app.add_option("--background", o.sizing.background_mesh,
                 "background mesh FILE.node (+ FILE.ele): area per vertex as the .node's one "
                 "attribute, or per triangle in FILE.area")
      ->check(CLI::ExistingFile);
  app.add_option("--area-grid", o.sizing.area_grid, "structured area grid file (see README)")
      ->check(CLI::ExistingFile);
  app.add_option("--subdomains", o.subdomains,
                 "number of subdomains (1: monolithic kernel; default: automatic)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 20));
  app.add_option("--max-triangles", o.max_triangles,
                 "refuse, before meshing, a run whose estimated triangle count exceeds N "
                 "(default: what fits in physical memory)")
      ->check(CLI::PositiveNumber);
  app.add_option("--threads", o.threads, threads_help)->check(CLI::Range(1u, 4096u));
  app.add_option("--r1", o.gradation.r1,
                 "graded method: Condition 1 bound M/m per subdomain (default 1.425)");
  app.add_option("--r2", o.gradation.r2,
                 "graded method: Condition 2 bound m_i/m_j across separators (default 1.5, < 3)");
  app.add_option("--geometric-sizing", o.geometric_sizing,
                 "decouple with the sizing function built from the geometry (Algorithm 8.3): "
                 "auto (default: when a feature is smaller than the mesh), on, off")
      ->check(CLI::IsMember({"auto", "on", "off"}));
  auto* per = app.add_option("--output-per-subdomain", o.per_subdomain_dir,
                             "write one .vtu per subdomain and an index mesh.pvtu into DIR "
                             "(nothing is kept in memory)");
  app.add_option("--stats", o.stats, "write statistics as JSON to this file");
  app.add_flag("-q,--quiet", o.quiet, "print nothing but errors");
  return per;
}

/// The generate_options of a run on `domain` (read and validated): the criteria, N, threads,
/// the triangle limit and the sizing field (see sizing_field; `sizing_kind` names it for --stats).
/// \throws as sizing_field.
inline pdd::generate_options generate_options_for(const mesh_options& o, const pdd::pslg& domain,
                                                  std::string& sizing_kind) {
  pdd::generate_options g;
  g.criteria = {.min_angle_deg = o.min_angle, .max_area = o.max_area};
  g.subdomains = o.subdomains;
  g.threads = o.threads;
  g.max_triangles = o.max_triangles;
  g.gradation = o.gradation;
  g.geometric_sizing = o.geometric_sizing == "on"    ? pdd::geometric_sizing_mode::on
                       : o.geometric_sizing == "off" ? pdd::geometric_sizing_mode::off
                                                     : pdd::geometric_sizing_mode::automatic;
  g.sizing = sizing_field(o.sizing, domain, o.max_area, sizing_kind);
  return g;
}

} // namespace pdd::drivers
