// pdd-verify: verifies a per-subdomain mesh (pdd-mesh --output-per-subdomain DIR, VTU or
// --format binary) one piece at a time, without loading it whole (pdd::verify_pieces): every piece
// alone as pdd::verify does, then every interface (shared edges bitwise equal from both sides,
// exact Delaunay across them).
//
//   pdd-verify DIR/mesh.{pvtu,pddi} INPUT.poly [--min-angle DEG] [--max-area A] [--stats FILE.json]
//              [--max-reported K] [--quiet]
//
// Exit codes: 0 the mesh passed, 1 a file cannot be read or is not pdd's format (truncated,
// tampered, foreign, another binary version), 2 usage, 3 the mesh failed verification, 4 internal
// error.
#include "exit_code.hpp"
#include "version_flag.hpp"

#include <pdd/io/atomic_file.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/mesh/verify_pieces.hpp>
#include <pdd/pipeline/system.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <string>

namespace {

using namespace pdd::drivers; // exit codes

struct cli_options {
  std::string index, input, stats;
  pdd::mesh_criteria criteria;
  std::size_t max_reported = 20;
  bool quiet = false;
};

nlohmann::json to_json(const pdd::pieces_report& r, double seconds) {
  nlohmann::json j;
  j["ok"] = r.ok();
  j["pieces"] = r.pieces;
  j["triangles"] = r.triangles;
  j["vertices"] = r.vertices;
  j["largest_piece_triangles"] = r.largest_piece_triangles;
  j["interface_edges"] = r.interface_edges;
  j["domain_boundary_edges"] = r.domain_boundary_edges;
  j["max_open_edges"] = r.max_open_edges;
  j["delaunay_violations"] = r.delaunay_violations;
  j["orientation_violations"] = r.orientation_violations;
  j["duplicate_vertices"] = r.duplicate_vertices;
  j["quality_violations"] = r.quality_violations;
  j["area_violations"] = r.area_violations;
  j["nonmanifold_edges"] = r.nonmanifold_edges;
  j["interface_overlaps"] = r.interface_overlaps;
  j["interface_delaunay_violations"] = r.interface_delaunay_violations;
  j["unmatched_edges"] = r.unmatched_edges;
  j["area_domain"] = r.area_domain;
  j["area_mesh"] = r.area_mesh;
  j["area_ok"] = r.area_ok;
  j["messages"] = r.messages;
  j["seconds"] = seconds;
  j["peak_rss_mib"] = pdd::peak_rss_mib();
  return j;
}

void print_report(const pdd::pieces_report& r) {
  std::printf("pdd-verify: %zu pieces, %zu triangles (largest piece %zu), %zu interface edges "
              "checked, %zu domain boundary edges\n",
              r.pieces, r.triangles, r.largest_piece_triangles, r.interface_edges,
              r.domain_boundary_edges);
  std::printf("  in the pieces: %zu not Delaunay, %zu orientation, %zu duplicate vertices, %zu "
              "quality, %zu area, %zu nonmanifold\n",
              r.delaunay_violations, r.orientation_violations, r.duplicate_vertices,
              r.quality_violations, r.area_violations, r.nonmanifold_edges);
  std::printf("  across interfaces: %zu unmatched edges, %zu overlaps, %zu not Delaunay; area "
              "%.17g of %.17g (%s)\n",
              r.unmatched_edges, r.interface_overlaps, r.interface_delaunay_violations, r.area_mesh,
              r.area_domain, r.area_ok ? "ok" : "differs");
  for (const std::string& m : r.messages)
    std::printf("  %s\n", m.c_str());
}

int run(const cli_options& o) {
  const auto start = std::chrono::steady_clock::now();
  // read as pdd-mesh read it (verify_pieces validates it, geometry_error, and reads a domain
  // that is not one of closed loops by Triangle's rule: pdd::domain_as_generated)
  const pdd::pslg input = pdd::read_poly(o.input);
  pdd::verify_options vo{.criteria = o.criteria, .max_reported = o.max_reported};
  const pdd::pieces_report r = pdd::verify_pieces(o.index, input, vo);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.quiet || !r.ok()) print_report(r);
  if (!o.stats.empty()) {
    const nlohmann::json j = to_json(r, seconds);
    pdd::write_file_atomically(o.stats, [&](std::ostream& os) { os << j.dump(2) << '\n'; });
  }
  std::printf("pdd-verify: verification %s (%.2f s)\n", r.ok() ? "passed" : "FAILED", seconds);
  return r.ok() ? ok : verification_failed;
}

} // namespace

int main(int argc, char** argv) {
  cli_options o;
  CLI::App app{"pdd-verify: verify a per-subdomain mesh (.pvtu over .vtu pieces, or .pddi over "
               "binary .pddm pieces) piece by piece"};
  pdd::drivers::add_version_flag(app, "pdd-verify");
  app.add_option("index", o.index,
                 "the index, mesh.pvtu or mesh.pddi (pdd-mesh --output-per-subdomain DIR)")
      ->required();
  app.add_option("input", o.input, "the input domain it meshes (Triangle .poly)")->required();
  app.add_option("--min-angle", o.criteria.min_angle_deg,
                 "minimum angle in degrees (default 20.7, as pdd-mesh)")
      ->check(CLI::Range(0.0, 60.0));
  app.add_option("--max-area", o.criteria.max_area, "maximum triangle area (default: none)")
      ->check(CLI::PositiveNumber);
  app.add_option("--stats", o.stats, "write the counts and messages as JSON to this file");
  app.add_option("--max-reported", o.max_reported, "how many problems to describe (default 20)");
  app.add_flag("-q,--quiet", o.quiet, "print only the verdict (and the problems, if any)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return pdd::drivers::run_reporting_errors("pdd-verify", o.input, [&] { return run(o); });
}
