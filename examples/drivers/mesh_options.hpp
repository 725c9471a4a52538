/// \file mesh_options.hpp
/// The options pdd-mesh and pdd-mesh-mpi share (the input, the quality and sizing criteria, N,
/// threads, --max-triangles, the per-subdomain output and its --format, the disk-space check,
/// --stats, --quiet), registered once for both, and the generate_options they give.
#pragma once

#include "sizing_options.hpp"

#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/piece_files.hpp>
#include <pdd/madd/gradation_options.hpp>
#include <pdd/pipeline/options.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <system_error>

namespace pdd::drivers {

/// The --kernel default: cgal, or native in a PDD_PERMISSIVE build (no CGAL Mesh_2).
#ifdef PDD_PERMISSIVE
inline constexpr const char* default_kernel_name = "native";
#else
inline constexpr const char* default_kernel_name = "cgal";
#endif

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
  /// --geometric-max-subdomains: the geometric loop's cap (geometric_decompose_options)
  std::size_t geometric_max_subdomains = pdd::geometric_decompose_options{}.max_subdomains;
  std::string geometric_field = "user"; // --geometric-field: user (f) or 8.3 (Algorithm 8.3's F)
  bool quiet = false;
  /// --format: the per-subdomain output's file format (vtu: .vtu + mesh.pvtu; binary: .pddm +
  /// mesh.pddi)
  pdd::piece_format format = pdd::piece_format::vtu;
  bool no_disk_check = false; ///< --no-disk-check
  /// --kernel: cgal (pdd::cgal::mesher, the default) or native (pdd::native::mesher; the
  /// default and the only one in a PDD_PERMISSIVE build)
  std::string kernel = default_kernel_name;
  std::optional<std::uintmax_t> assume_free_bytes; ///< --assume-free-bytes (for tests)
};

/// Registers the sizing fields' options (--sizing, --background, --area-grid) on `app`.
inline void add_sizing_options(CLI::App& app, sizing_sources& sizing) {
  app.add_option("--sizing", sizing.expression,
                 "maximum triangle area as an expression of x and y (muParser), e.g. "
                 "\"1e-4*(1+10*x^2)\"");
  app.add_option("--background", sizing.background_mesh,
                 "background mesh FILE.node (+ FILE.ele): area per vertex as the .node's one "
                 "attribute, or per triangle in FILE.area")
      ->check(CLI::ExistingFile);
  app.add_option("--area-grid", sizing.area_grid, "structured area grid file (docs/formats.md)")
      ->check(CLI::ExistingFile);
}

/// Registers --output-per-subdomain, its --format and the disk-space check's options on `app`;
/// returns the --output-per-subdomain option.
inline CLI::Option* add_output_options(CLI::App& app, mesh_options& o) {
  auto* per = app.add_option("--output-per-subdomain", o.per_subdomain_dir,
                             "write one file per subdomain and an index (mesh.pvtu or mesh.pddi, "
                             "see --format) into DIR (nothing is kept in memory)");
  const std::map<std::string, pdd::piece_format> formats{{"vtu", pdd::piece_format::vtu},
                                                         {"binary", pdd::piece_format::binary}};
  app.add_option("--format", o.format,
                 "file format of --output-per-subdomain: vtu (default; .vtu pieces, mesh.pvtu) or "
                 "binary (.pddm pieces, mesh.pddi: about 15 instead of 35 bytes per triangle, "
                 "docs/binary-mesh-format.md; pdd-convert turns it into VTU)")
      ->transform(CLI::CheckedTransformer(formats))
      ->needs(per);
  auto* no_check = app.add_flag("--no-disk-check", o.no_disk_check,
                                "do not refuse, up front, a per-subdomain output larger than the "
                                "free space of its file system (estimated from the mesh size)");
  app.add_option("--assume-free-bytes", o.assume_free_bytes,
                 "for tests: let the disk-space check take this many bytes as the free space")
      ->excludes(no_check)
      ->needs(per);
  return per;
}

/// Registers the method's options on `app`: the graded method's --r1 and --r2, the geometric
/// sizing (--geometric-sizing, --geometric-max-subdomains, --geometric-field) and the kernel
/// (--kernel).
inline void add_method_options(CLI::App& app, mesh_options& o) {
  app.add_option("--r1", o.gradation.r1,
                 "graded method: Condition 1 bound M/m per subdomain (default 1.425)");
  app.add_option("--r2", o.gradation.r2,
                 "graded method: Condition 2 bound m_i/m_j across separators (default 1.5, < 3)");
  app.add_option("--geometric-sizing", o.geometric_sizing,
                 "decouple with the sizing function built from the geometry (Algorithm 8.3): "
                 "auto (default: when a feature is smaller than the mesh), on, off")
      ->check(CLI::IsMember({"auto", "on", "off"}));
  app.add_option("--geometric-max-subdomains", o.geometric_max_subdomains,
                 "geometric path: the most subdomains its rounds of Algorithm 7.1 may make "
                 "(default 4096)")
      ->check(CLI::Range(std::size_t{2}, std::size_t{1} << 24));
  app.add_option("--geometric-field", o.geometric_field,
                 "geometric path: mesh with the user's area bound (user, default) or with "
                 "Algorithm 8.3's F (8.3)")
      ->check(CLI::IsMember({"user", "8.3"}));
#ifdef PDD_PERMISSIVE
  app.add_option("--kernel", o.kernel,
                 "sequential Delaunay refinement kernel: native (pdd's triangle-array mesher; "
                 "this build has no other)")
      ->check(CLI::Validator(
          [](const std::string& k) {
            return k == "native" ? std::string()
                                 : "the " + k +
                                       " kernel is not in this build of pdd (built with "
                                       "PDD_PERMISSIVE: no GPL code); use --kernel native";
          },
          "native"));
#else
  app.add_option("--kernel", o.kernel,
                 "sequential Delaunay refinement kernel: cgal (default, CGAL's Mesh_2) or native "
                 "(pdd's triangle-array mesher)")
      ->check(CLI::IsMember({"cgal", "native"}));
#endif
}

/// True when a region of the domain carries a nonzero attribute (Triangle's -A): pdd-mesh
/// writes them with -A and says so without it; pdd-mesh-mpi says it does not write them.
inline bool has_region_attributes(const pdd::pslg& g) {
  return std::any_of(g.regions.begin(), g.regions.end(),
                     [](const pdd::region& r) { return r.attribute != 0.0; });
}

/// Registers the shared options on `app` (`threads_help` describes --threads) and returns the
/// --output-per-subdomain option (pdd-mesh excludes other outputs with it).
inline CLI::Option* add_mesh_options(CLI::App& app, mesh_options& o,
                                     const std::string& threads_help) {
  app.add_option("input", o.input, "input domain (Triangle .poly)")->required();
  app.add_option("--min-angle", o.min_angle, "minimum angle in degrees (default 20.7)")
      ->check(CLI::Range(1.0, 34.0));
  app.add_option("--max-area", o.max_area, "maximum triangle area")->check(CLI::PositiveNumber);
  add_sizing_options(app, o.sizing);
  app.add_option("--subdomains", o.subdomains,
                 "number of subdomains (1: monolithic kernel; default: automatic)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 20));
  app.add_option("--max-triangles", o.max_triangles,
                 "refuse, before meshing, a run whose estimated triangle count exceeds N "
                 "(default: what fits in physical memory)")
      ->check(CLI::PositiveNumber);
  app.add_option("--threads", o.threads, threads_help)->check(CLI::Range(1u, 4096u));
  add_method_options(app, o);
  auto* per = add_output_options(app, o);
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
  g.geometric_loop.max_subdomains = o.geometric_max_subdomains;
  g.geometric_field = o.geometric_field == "8.3" ? pdd::geometric_mesh_field::algorithm_8_3
                                                 : pdd::geometric_mesh_field::user;
  g.sizing = sizing_field(o.sizing, domain, o.max_area, sizing_kind);
  return g;
}

/// The free bytes of the file system that will hold `dir` (asked of its nearest existing
/// ancestor: the output folder may not exist yet).
/// \throws pdd::error when the file system cannot be asked.
inline std::uintmax_t free_bytes_for(const std::filesystem::path& dir) {
  std::filesystem::path p = std::filesystem::absolute(dir);
  while (!std::filesystem::exists(p) && p.has_parent_path() && p != p.parent_path())
    p = p.parent_path();
  std::error_code ec;
  const std::filesystem::space_info s = std::filesystem::space(p, ec);
  if (ec) throw pdd::error("cannot ask the free space of '" + p.string() + "': " + ec.message());
  return s.available;
}

/// The disk-space check before a per-subdomain output (unless --no-disk-check): the estimated
/// bytes of `triangles` triangles in `pieces` pieces of the chosen --format
/// (pdd::estimated_piece_bytes) against the free space of the output folder's file system (or
/// --assume-free-bytes), to which `reused` adds the bytes of pieces already on disk (those a
/// --resume keeps). Non-finite estimates are not checked.
/// \throws pdd::limit_error (exit code 1) with the estimate and the free space when it does
/// not fit; pdd::error when the free space cannot be asked.
inline void check_disk_space(const mesh_options& o, double triangles, std::size_t pieces,
                             std::uintmax_t reused = 0) {
  if (o.no_disk_check || o.per_subdomain_dir.empty() || !(triangles >= 0.0) ||
      triangles == std::numeric_limits<double>::infinity())
    return;
  const double need = pdd::estimated_piece_bytes(
      o.format, triangles, static_cast<double>(std::max<std::size_t>(1, pieces)));
  const std::uintmax_t free =
      reused + (o.assume_free_bytes ? *o.assume_free_bytes : free_bytes_for(o.per_subdomain_dir));
  if (need <= static_cast<double>(free)) return;
  char text[2048];
  std::snprintf(
      text, sizeof text,
      "the per-subdomain output would need about %.3g bytes on disk (%.4g estimated "
      "triangles in %zu pieces, %s format, about %.1f bytes per triangle), but the file "
      "system of '%s' has %.3g bytes free%s. Free some space, write elsewhere, %sor use a "
      "larger --max-area, or skip this check with --no-disk-check",
      need, triangles, pieces, pdd::to_string(o.format), triangles > 0 ? need / triangles : 0.0,
      o.per_subdomain_dir.c_str(), static_cast<double>(free),
      o.assume_free_bytes ? " (--assume-free-bytes)" : "",
      o.format == pdd::piece_format::vtu
          ? "use --format binary (about 14 bytes per triangle against VTU's 35) "
          : "");
  throw pdd::limit_error(text);
}

} // namespace pdd::drivers
