// pdd-triangle: a Triangle-compatible command. `pdd-triangle -pq30a0.01 key.poly` reads and
// writes the files `triangle -pq30a0.01 key.poly` does (key.1.node, key.1.ele, key.1.poly) and
// prints Triangle's statistics, with pdd's decoupled pipeline doing the meshing.
//
//   pdd-triangle [-SWITCHES ...] INPUT[.poly] [--threads T] [--subdomains N]
//
// Switches (Triangle 1.6's letters; pdd::triangle::parse_switches): p, r, q[angle], a[area],
// a (regional area bounds), A, c, D, S[n], e, v, o2, C (pdd's verifier), Q, V, N, E, P, B, I,
// O, z, j, n (and i F l s L X, ignored). Without p (and a .poly name) the input is a vertex set,
// NAME.node. Every other switch is refused by name, with the reason.
// Exit codes: 0 ok, 1 bad input, 2 usage (an unsupported switch), 3 the check of -C failed (the
// files are written), 4 internal error, 5 an input beyond double precision.
#include "exit_code.hpp"
#include "version_flag.hpp"

#include <pdd/errors.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/io/previous_mesh.hpp>
#include <pdd/io/triangle_files.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/region_attributes.hpp>
#include <pdd/parallel/parallel_for.hpp>
#include <pdd/triangle/file_names.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulate.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using pdd::drivers::bad_input;
using pdd::drivers::internal;
using pdd::drivers::ok;
using pdd::drivers::unresolvable;
using pdd::drivers::usage;
using pdd::drivers::verification_failed;

struct cli_options {
  std::string input;
  std::vector<std::string> switch_args; ///< the -... arguments, in order
  pdd::triangle::triangulate_options run;
};

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

/// Triangle's -V block: extremes and the angle histogram in 10-degree bins.
void print_quality(const pdd::triangle_mesh& m) {
  const pdd::mesh_statistics q = pdd::compute_statistics(m);
  std::printf("Mesh quality statistics:\n\n");
  std::printf("  Largest area: %.6g  |  Largest radius-edge ratio: %.6g\n", q.max_area,
              q.max_ratio);
  std::printf("  Smallest angle: %.6g  |  Largest angle: %.6g\n\n", q.min_angle_deg,
              q.max_angle_deg);
  std::printf("  Angle histogram:\n");
  for (int b = 0; b < 9; ++b) {
    std::size_t lo = 0, hi = 0;
    for (int d = 0; d < 10; ++d) {
      lo += q.angle_histogram[static_cast<std::size_t>(10 * b + d)];
      hi += q.angle_histogram[static_cast<std::size_t>(90 + 10 * b + d)];
    }
    std::printf("    %3d - %3d degrees: %8zu    |  %3d - %3d degrees: %8zu\n", 10 * b, 10 * b + 10,
                lo, 90 + 10 * b, 100 + 10 * b, hi);
  }
  std::printf("\n");
}

/// Triangle's closing statistics block (segments and holes with -p only; the mesh vertices
/// without the ignored duplicates of a vertex set, as Triangle counts them).
void print_statistics(const pdd::pslg& in, const pdd::triangle::triangulation& t,
                      const pdd::triangle::switches& sw) {
  const auto nb = t.neighbors.empty() ? pdd::triangle_neighbors(t.mesh) : t.neighbors;
  const auto e = pdd::triangle::detail::count_edges(nb);
  std::printf("\nStatistics:\n\n  Input vertices: %zu\n", in.vertices.size());
  if (sw.poly) {
    std::printf("  Input segments: %zu\n", in.segments.size());
    std::printf("  Input holes: %zu\n", in.holes.size());
  }
  const std::size_t ignored = sw.jettison ? 0 : t.duplicate_vertices.size();
  std::printf("\n  Mesh vertices: %zu\n  Mesh triangles: %zu\n", t.mesh.vertices.size() - ignored,
              t.mesh.triangles.size());
  std::printf("  Mesh edges: %zu\n  Mesh exterior boundary edges: %zu\n", e.edges, e.boundary);
  if (sw.poly) {
    std::printf("  Mesh interior boundary edges: %zu\n", t.mesh.segments.size() - e.boundary);
    std::printf("  Mesh subsegments (constrained edges): %zu\n", t.mesh.segments.size());
  }
  std::printf("\n");
}

/// True when D or S take the whole domain on one triangulation (a PSLG, a previous mesh, or a
/// vertex set's hull with q or a; detail::conforming_path).
bool one_triangulation(const pdd::triangle::switches& sw) {
  return (sw.poly || sw.quality || sw.refine) && pdd::triangle::detail::conforming_path(sw);
}

/// How long meshing took, in how many subdomains, and how the pipeline read the domain.
void report_meshing(const pdd::triangle::triangulation& t, const pdd::triangle::switches& sw,
                    double ms) {
  if (one_triangulation(sw)) {
    std::printf("Mesh milliseconds:  %.0f (1 subdomain: -D and -S mesh the whole domain)\n\n", ms);
    return;
  }
  if (t.runs.empty()) { // no q or a: the (constrained) Delaunay triangulation
    std::printf("Delaunay milliseconds:  %.0f\n\n", ms);
    return;
  }
  std::size_t n = 0;
  for (const auto& r : t.runs)
    n += r.subdomains;
  std::printf("Mesh milliseconds:  %.0f (%zu subdomain(s))\n\n", ms, n);
  if (t.strips > 1)
    std::printf("The vertex set's hull was decoupled into %zu strips, their separators through "
                "the vertices.\n",
                t.strips);
  else if (t.runs.front().general_domain)
    std::printf("The domain is not one of closed loops (internal or dangling segments, "
                "isolated vertices, touching loops or internal boundaries): %s.\n",
                n > 1 ? "decoupled from its faces, the segments between faces as interfaces"
                      : "meshed whole");
}

/// Writes one output file (or says it does not) as Triangle reports it.
template <class Write>
void output(const std::string& name, const char* not_written, bool quiet, Write write) {
  if (name.empty()) {
    if (!quiet) std::printf("NOT writing %s.\n", not_written);
    return;
  }
  if (!quiet) std::printf("Writing %s.\n", name.c_str());
  write(name);
}

/// The switches of all single-dash arguments, in order.
/// \throws switch_error for a refused switch.
pdd::triangle::switches read_switches(const cli_options& o) {
  pdd::triangle::switches sw;
  for (const std::string& a : o.switch_args)
    sw = pdd::triangle::parse_switches(a, sw);
  return sw;
}

/// The input: the .poly with -p, else the .node (a vertex set).
pdd::pslg read_input(const pdd::triangle::file_names& f, const pdd::triangle::switches& sw) {
  if (!sw.quiet) std::printf("Opening %s.\n", (sw.poly ? f.poly : f.in_node).c_str());
  return sw.poly ? pdd::read_poly(f.poly) : pdd::read_node(f.in_node);
}

/// -r: the previous mesh (.node, .ele; with -p its .poly; with a bare -a its .area if present).
pdd::previous_mesh read_previous(const pdd::triangle::file_names& f,
                                 const pdd::triangle::switches& sw) {
  if (!sw.quiet) std::printf("Opening %s.\nOpening %s.\n", f.in_node.c_str(), f.in_ele.c_str());
  const bool area = !f.in_area.empty() && std::filesystem::exists(f.in_area);
  if (!sw.quiet && area) std::printf("Opening %s.\n", f.in_area.c_str());
  return pdd::read_previous_mesh(f.base, sw.poly, area);
}

/// Triangle's warning for every input vertex equal to an earlier one (without -p).
void input_warnings(const pdd::pslg& in, const pdd::triangle::triangulation& t) {
  for (const auto& d : t.duplicate_vertices)
    std::printf("Warning:  A duplicate vertex at %s appeared and was ignored (vertex %zu is "
                "vertex %zu).\n",
                pdd::to_string(in.vertices[d[0]]).c_str(), std::size_t{d[0]}, std::size_t{d[1]});
}

/// Why the mesh of a PSLG that encloses no domain is empty (on stderr, even with Q: an empty
/// mesh is never silent).
void empty_domain_warning(const std::string& input, const pdd::triangle::triangulation& t) {
  if (!t.empty_domain.empty())
    std::fprintf(stderr,
                 "pdd-triangle: warning: %s: %s; the mesh has no triangles (as Triangle's)\n",
                 input.c_str(), t.empty_domain.c_str());
}

/// -C: pdd::verify's verdict (the messages on stderr); verification_failed when it failed.
int check_outcome(const pdd::triangle::triangulation& t, const pdd::triangle::switches& sw) {
  if (!t.check) return ok;
  if (t.check->ok()) {
    if (!sw.quiet)
      std::printf("Checked the mesh with pdd's verifier (-C): exact Delaunay, conformity, the "
                  "domain's area and the bounds hold.\n");
    return ok;
  }
  std::fprintf(stderr, "pdd-triangle: the mesh check (-C, pdd's verifier) FAILED\n");
  for (const std::string& m : t.check->messages)
    std::fprintf(stderr, "  %s\n", m.c_str());
  return verification_failed;
}

/// Writes the .node, .ele, .poly and .neigh files the switches ask for.
void write_outputs(const pdd::triangle::file_names& f, const pdd::triangle::switches& sw,
                   const pdd::pslg& in, const pdd::triangle::triangulation& t) {
  pdd::triangle_format fmt;
  fmt.first_index = sw.zero_based ? 0 : 1;
  fmt.markers = !sw.no_boundary_markers;
  fmt.marker_attribute = false;
  output(f.node, "a .node file", sw.quiet, [&](const std::string& p) {
    pdd::write_node(p, t.mesh, fmt, t.vertex_attributes, t.vertex_attribute_count);
  });
  output(f.ele, "an .ele file", sw.quiet, [&](const std::string& p) {
    pdd::write_ele(p, t.mesh, fmt, t.triangle_attributes, t.second_order);
  });
  if (sw.poly || sw.convex) // Triangle writes segments only for a PSLG or with c
    output(f.out_poly, "a .poly file", sw.quiet,
           [&](const std::string& p) { pdd::write_mesh_poly(p, t.mesh, fmt, in.holes); });
  const auto also = [&sw](const std::string& name) {
    if (!name.empty() && !sw.quiet) std::printf("Writing %s.\n", name.c_str());
    return !name.empty();
  };
  if (also(f.neigh)) pdd::write_neigh(f.neigh, t.neighbors, fmt);
  if (also(f.edge)) pdd::write_edge(f.edge, t.edges, fmt);
  if (also(f.v_node) && also(f.v_edge))
    pdd::write_voronoi(f.v_node, f.v_edge, t.voronoi.vertices, t.voronoi.edges,
                       t.voronoi.directions, fmt);
}

/// What pdd-triangle is about to do, as Triangle announces it; with V the switches it ignores.
void announce(const pdd::triangle::switches& sw) {
  if (sw.refine) std::printf("Refining the previous mesh.\n");
  std::printf(one_triangulation(sw)
                  ? "Meshing the whole domain on one triangulation (CGAL's Mesh_2: "
                    "conforming Delaunay with -D, at most -S Steiner points).\n"
              : sw.quality ? "Meshing with pdd's decoupled pipeline.\n"
              : sw.poly    ? "Constructing constrained Delaunay triangulation (CGAL).\n"
                           : "Constructing Delaunay triangulation (CGAL).\n");
  if (sw.verbose > 0 && !sw.ignored.empty())
    std::printf("Ignoring switch(es) -%s: they choose Triangle's internal algorithms, which pdd "
                "does not use.\n",
                sw.ignored.c_str());
  if (sw.second_order) std::printf("Adding vertices for second-order triangles.\n");
}

int run(const cli_options& o) {
  const auto t0 = std::chrono::steady_clock::now();
  pdd::triangle::switches sw = read_switches(o);
  pdd::triangle::switches probe = sw;
  const std::string base = pdd::triangle::make_file_names(o.input, probe).base; // sets p
  const bool node_read = !probe.poly || probe.refine || std::filesystem::exists(base + ".node");
  const pdd::triangle::file_names f = pdd::triangle::make_file_names(o.input, sw, node_read);
  pdd::previous_mesh previous;
  if (sw.refine)
    previous = read_previous(f, sw);
  else
    previous.input = read_input(f, sw);
  const pdd::pslg& in = previous.input;
  if (!sw.quiet) announce(sw);
  const auto tm = std::chrono::steady_clock::now();
  const pdd::triangle::triangulation t = sw.refine ? pdd::triangle::refine(previous, sw, o.run)
                                                   : pdd::triangle::triangulate(in, sw, o.run);
  if (!sw.quiet) input_warnings(in, t);
  empty_domain_warning(o.input, t);
  if (!sw.quiet) report_meshing(t, sw, ms_since(tm));
  write_outputs(f, sw, in, t);
  if (!sw.quiet) {
    std::printf("\nTotal running milliseconds:  %.0f\n", ms_since(t0));
    print_statistics(in, t, sw);
    if (sw.verbose > 0) print_quality(t.mesh);
  }
  return check_outcome(t, sw);
}

int fail(const char* what, const std::exception& e, int code) {
  std::fprintf(stderr, "pdd-triangle: %s: %s\n", what, e.what());
  return code;
}

/// run(o) on at most --threads threads, with every error reported on stderr and mapped to its exit
/// code.
int run_reporting_errors(const cli_options& o) {
  try { // --threads T: nothing of the run on more than T threads
    return pdd::with_threads(o.run.threads, [&] { return run(o); });
  } catch (const pdd::triangle::switch_error& e) {
    return fail("error", e, usage);
  } catch (const pdd::input_error& e) {
    return fail("error", e, bad_input);
  } catch (const pdd::geometry_error& e) {
    std::fprintf(stderr, "pdd-triangle: error: %s: %s\n", o.input.c_str(), e.what());
    return bad_input;
  } catch (const pdd::internal_error& e) {
    return fail("internal error", e, internal);
  } catch (const pdd::unresolvable_input_error& e) { // an input limit, not a bug
    return fail("error", e, unresolvable);
  } catch (const pdd::meshing_error& e) {
    return fail("internal error", e, internal);
  } catch (const pdd::error& e) { // limits, decomposition, files that cannot be read or written
    return fail("error", e, bad_input);
  } catch (const std::exception& e) {
    return fail("internal error", e, internal);
  }
}

} // namespace

int main(int argc, char** argv) {
  cli_options o;
  // Triangle's switches (-pq30 ...) are not CLI11 options: take every single-dash argument
  // out before CLI11 parses the rest (--threads, --subdomains, --help, the input).
  std::vector<std::string> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.size() > 1 && a[0] == '-' && a[1] != '-')
      o.switch_args.push_back(a);
    else
      rest.push_back(a);
  }
  CLI::App app{"pdd-triangle: Triangle's command line (switches -pq30a0.01 ...), meshed by pdd"};
  app.add_option("input", o.input,
                 "input: NAME.poly, or NAME with -p; NAME or NAME.node without -p (a vertex set)")
      ->required();
  app.add_option("--subdomains", o.run.subdomains,
                 "number of subdomains (1: monolithic kernel; default: automatic)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 20));
  app.add_option("--threads", o.run.threads, "threads (default: all cores)")
      ->check(CLI::Range(1u, 4096u));
  app.footer("Switches (Triangle 1.6's meaning): p (mesh a PSLG; without it the input is a "
             "vertex set, triangulated), r (refine NAME's .node/.ele), q[angle], a[area], a "
             "(regional areas), A, c (convex hull), D (conforming Delaunay: every triangle "
             "Delaunay, segments split; the whole domain on one triangulation), S[n] (at most n "
             "Steiner points; with q, a or D the whole domain on one triangulation), e (.edge), v "
             "(Voronoi: .v.node, .v.edge), o2, C (check the mesh with pdd's verifier; exit 3 when "
             "it fails), Q, V, N, E, P, B, I, O, z, j, n; i F l s L X are accepted and ignored. "
             "Refused, with the reason: u w W Y g.");
  // --version (CLI11) exits before Triangle's switches are read (run_reporting_errors)
  pdd::drivers::add_version_flag(app, "pdd-triangle");
  try {
    std::vector<const char*> args;
    for (const std::string& a : rest)
      args.push_back(a.c_str());
    app.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? ok : usage;
  }
  return run_reporting_errors(o);
}
