// libFuzzer target over the whole user path of pdd-mesh: the bytes are read as a Triangle .poly
// (pdd::parse_poly from memory), validated, meshed by pdd::generate with N = 1 and N = 2, and
// every mesh is checked by pdd::verify with its default options, as README's library example
// calls it (on the PSLG given to generate; it reads the faces and picks the exemptions itself,
// as pdd-mesh --verify does; half the inputs are meshed under the diametral lens, Triangle's
// rule for -q without -D, and verified as constrained Delaunay): exact Delaunay, orientation,
// conformity to the input
// segments, the domain area covered, the area bound, and the angle bound on every triangle that
// is not exempt.
//
// Two kinds of domain (pdd::has_closed_loops):
// - closed loops: decoupled for N = 2; exempt from the angle bound are the shielded corners
//   (dissertation 8.1, pdd::find_shielded_triangles) only.
// - general domains (internal constraint segments, dangling segments, isolated vertices, loops
//   that touch at pinch vertices, loops nested without a hole point; issue 13): meshed whole by
//   Triangle's rule. N = 1 is verified against the domain read by Triangle's rule
//   (pdd::domain_rule::triangle): every segment with a domain face on a side, internal and
//   dangling ones included, a union of mesh edges (one with no domain face on either side, e.g.
//   dangling outside the domain, is left out of the mesh as Triangle 1.6 does), every isolated
//   vertex in the domain a mesh vertex, the area of the faces; exempt from the angle bound are
//   the cluster-exempt triangles at angles < 60 deg between segments
//   (pdd::find_cluster_exempt_triangles) only. N = 2 decouples it from its faces (N raised to
//   the number of faces; the segments between faces are interfaces; dangling segments and
//   isolated vertices inside subdomains, no separator near them) and is verified the same
//   way (a shielded corner has its vertices on the two segments of a small angle, so the
//   cluster exemption covers it; a face that touches itself at a pinch vertex is shielded per
//   sector, a corner with a segment inside the face from its apex is left to the kernel's
//   clusters, a corner < 60 deg on a segment between faces gets a cap, one subdomain), or
//   refuses it with a pdd::decomposition_error (MADD finds no separator clear of a face's
//   features); a meshing_error or any other exception there is a finding.
//
// Refusals of bad input before meshing are passes: pdd::input_error (parser), pdd::error from
// the parser (a .poly with 0 vertices names a .node file that cannot be read) and validate()'s
// pdd::geometry_error. Once validate() accepted the input, a refusal by pdd::generate is a
// finding unless it is one of the documented classes below (documented_refusals, each with the
// test that shows it), matched by its exception type and message:
// - decomposition_error "... connected components ..., more than the N subdomains asked for"
//   (pipeline.Generate.MoreComponentsThanSubdomainsIsRefused);
// - decomposition_error "MADD: cannot split the domain ..." (MADD finds no separator;
//   madd.MaddDecompose.UnsplittableGivesError);
// - on general domains only, the CGAL kernel's pdd::unresolvable_input_error for two segments at
//   a sub-degree angle ("... cannot be split: its rounded split point falls beyond a
//   neighbouring segment",
//   kernels.CgalMesherTriangleRule.UnresolvableAngleIsAnUnresolvableInputError), when two of the
//   input's segments do meet at a shared vertex at less than 1 deg.
// (A geometry_error from the shields, say, is a finding: Lemma 23 excludes it for generate's
// l <= lfs_min.) The counts of every class are printed at exit, and PDD_FUZZ_BOUNDS (set by the
// ctest test) puts floors on the inputs meshed and verified and a ceiling on those skipped, as
// fractions of all inputs: a run that tested less than it should fails though nothing crashed.
// Everything else aborts, and libFuzzer keeps the input: any other exception (internal_error,
// meshing_error, decoupling_error, std::exception), a crash, a sanitizer report,
// or a mesh that fails verification.
//
// The area bound is A = area / d, d in [8, 4096] (log-uniform) taken from a hash of the input's
// bytes, so every input is meshed the same way each time and coarse meshes (where the angle bound
// is hardest to keep) are tried as well as fine ones.
//
// Limits that keep every input small (valid inputs beyond them are skipped, not reported): at
// most max_input_bytes bytes and max_vertices vertices; the area alone asks for about 1.5 d
// <= 6200 triangles; and the quality bound alone asks for about
// c * integral of dA / lfs(x)^2 triangles (Ruppert's size optimality). Since lfs(x) >= lfs_min
// and lfs(x) >= the distance to the boundary, the part of the domain within t of the boundary
// has area <= P t (P: the total segment length) and the integral is <= 4 P / lfs_min: inputs
// with P / lfs_min > max_perimeter_over_lfs are skipped. A needle of width 1 and length 4e9 (a
// valid input that needs billions of triangles) has P / lfs_min = 8e9. The bound does not see
// the thin parts next to a small input angle (their segments meet, so they do not lower
// lfs_min; the shields, or on general domains the kernel's clusters, cut them off): a triangle of
// base 1, height 1317 and a 0.04 deg apex (P / lfs_min = 2635) took 24 s under ASan on a loaded
// machine, hence -timeout=300.
//
// General domains need both numbers changed. pdd::lfs_min is defined on closed loops: it
// throws pdd::geometry_error for a vertex that is not on exactly two segments (find_loops), and
// on loops nested without a hole point it measures the odd-nesting domain, not the faces that
// are meshed. So a general domain's lfs_min is bounded from below by general_lfs_lower_bound:
// the smallest distance between two vertices or a vertex and a segment not incident to it over
// the whole PSLG (isolated vertices and dangling segments included, visibility in the domain
// ignored, so it is <= Definition 7's lfs_min). And the domain lies on both sides of an internal
// or dangling segment and all round an isolated vertex: with F the segments and vertices, the
// area within t of F is <= 2 P t + pi V t^2 (V vertices, their disks cover the segments' ends),
// so the integral is <= 4 (2 P) / lfs_min + 2 pi V ln(P / lfs_min). The skip rule takes
// 2 P / lfs_min for general domains; the vertex term is bounded by max_vertices (at most
// 2 pi 256 ln(1e4) ~ 1.5e4, below the segment term's 8e4 at the limit).
#include <pdd/errors.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/lfs.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/mesh/cluster_exempt.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/shielding/shield_statistics.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace {

constexpr std::size_t max_input_bytes = 8192;
constexpr std::size_t max_vertices = 256;
constexpr double max_perimeter_over_lfs = 20000.0;
/// Below this angle between two segments at a shared vertex the CGAL kernel may refuse a
/// general domain with its documented meshing_error (see the file comment).
constexpr double unresolvable_angle_deg = 1.0;

/// What happened to the inputs, by kind of domain (0: closed loops, 1: general), printed at
/// exit so that a run shows how many inputs were meshed and verified rather than skipped.
struct outcome_counts {
  std::size_t inputs = 0;              // every input of at most max_input_bytes
  std::size_t refused_input = 0;       // parser or validate() refused the bytes, > 256 vertices
  std::size_t skipped[2] = {0, 0};     // beyond the size limits
  std::size_t verified[2] = {0, 0};    // N = 1 meshed and verified
  std::size_t refused[2] = {0, 0};     // N = 1 refused (geometry, decomposition, limit error)
  std::size_t angle_refusals = 0;      // general: the kernel's documented sub-degree angle refusal
  std::size_t n2_verified[2] = {0, 0}; // N = 2 meshed and verified
  std::size_t n2_refused[2] = {0, 0};  // N = 2 refused (geometry, decomposition, limit error)
};
outcome_counts counts;

/// A documented refusal of a validated input by generate() (see the file comment).
struct documented_refusal {
  const char* type;
  const char* message; // a part of the message that names the class
};
constexpr documented_refusal documented_refusals[] = {
    {"decomposition_error", "connected components (faces, for a general PSLG), more than the"},
    {"decomposition_error", "MADD: cannot split the domain"},
};

/// Refusals of validated inputs by generate(), by exception type and message with its numbers
/// blanked (printed at exit).
std::map<std::string, std::size_t> refusal_tally;

std::string refusal_key(const char* type, const std::string& what) {
  std::string key = std::string(type) + ": ";
  for (char ch : what.substr(0, 120))
    if (ch >= '0' && ch <= '9') {
      if (key.back() != '#') key += '#';
    } else {
      key += ch;
    }
  return key;
}

void print_counts() {
  for (const auto& [key, n] : refusal_tally)
    std::fprintf(stderr, "pdd fuzz refusal %6zu x %s\n", n, key.c_str());
  const outcome_counts& c = counts;
  std::fprintf(
      stderr,
      "pdd fuzz outcomes: %zu refused as input (or > 256 vertices); "
      "closed loops: %zu skipped (size), %zu verified N = 1, %zu refused N = 1, "
      "%zu verified N = 2, %zu refused N = 2; "
      "general: %zu skipped (size), %zu verified N = 1, "
      "%zu refused N = 1 (%zu for a sub-degree angle), %zu verified N = 2, %zu refused N = 2\n",
      c.refused_input, c.skipped[0], c.verified[0], c.refused[0], c.n2_verified[0], c.n2_refused[0],
      c.skipped[1], c.verified[1], c.refused[1] + c.angle_refusals, c.angle_refusals,
      c.n2_verified[1], c.n2_refused[1]);
}

/// The outcomes a run's bounds name (PDD_FUZZ_BOUNDS), as fractions of its inputs.
double outcome_fraction(const std::string& name) {
  const outcome_counts& c = counts;
  const std::pair<const char*, std::size_t> outcomes[] = {
      {"refused_input", c.refused_input},     {"skipped", c.skipped[0] + c.skipped[1]},
      {"loops_verified_n1", c.verified[0]},   {"loops_verified_n2", c.n2_verified[0]},
      {"general_verified_n1", c.verified[1]}, {"general_verified_n2", c.n2_verified[1]}};
  for (const auto& [key, n] : outcomes)
    if (name == key)
      return static_cast<double>(n) / static_cast<double>(std::max<std::size_t>(c.inputs, 1));
  std::fprintf(stderr, "PDD_FUZZ_BOUNDS: unknown outcome '%s'\n", name.c_str());
  std::_Exit(2);
}

/// Checks the run against PDD_FUZZ_BOUNDS ("outcome>=fraction" or "outcome<=fraction", comma
/// separated; fractions of the inputs): a run that meshed and verified too few inputs, or
/// skipped too many, tested less than it claims and fails (exit 1) though nothing crashed.
void check_outcome_bounds() {
  const char* text = std::getenv("PDD_FUZZ_BOUNDS");
  if (text == nullptr) return;
  std::istringstream list(text);
  bool ok = true;
  for (std::string bound; std::getline(list, bound, ',');) {
    const std::size_t op = bound.find_first_of("<>");
    if (op == std::string::npos || op + 1 >= bound.size() || bound[op + 1] != '=') {
      std::fprintf(stderr, "PDD_FUZZ_BOUNDS: '%s' is not outcome>=x or outcome<=x\n",
                   bound.c_str());
      std::_Exit(2);
    }
    const double have = outcome_fraction(bound.substr(0, op));
    const double want = std::stod(bound.substr(op + 2));
    const bool met = bound[op] == '>' ? have >= want : have <= want;
    std::fprintf(stderr, "pdd fuzz bound %s: %.4f of %zu inputs, %s\n", bound.c_str(), have,
                 counts.inputs, met ? "met" : "NOT MET");
    ok = ok && met;
  }
  if (!ok) std::_Exit(1);
}

void report_outcomes() {
  print_counts();
  check_outcome_bounds();
}

/// Reports a finding and aborts (libFuzzer then saves the input as crash-<hash>).
[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "pdd fuzz finding: %s\n", what.c_str());
  std::abort();
}

/// A domain to mesh: the PSLG as parsed (as pdd-mesh hands it to pdd::generate) and whether it
/// is a general one (not of closed loops: meshed whole by Triangle's rule).
struct fuzz_domain {
  pdd::pslg input;
  bool general = false;

  /// The domain as the pipeline reads it, for pdd::domain_area and pdd::verify.
  pdd::pslg as_meshed() const {
    pdd::pslg g = input;
    if (general) g.rule = pdd::domain_rule::triangle;
    return g;
  }
};

/// The parsed and validated domain, or nothing when the parser or validate() refuses it.
std::optional<fuzz_domain> read_domain(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    // A vertex count of 0 refers to a .node sibling: looked up under /dev/null, never found.
    fuzz_domain d{pdd::parse_poly(in, "fuzz.poly", "/dev/null")};
    if (d.input.vertices.size() > max_vertices) return std::nullopt;
    d.general = !pdd::has_closed_loops(d.input); // validates
    return d;
  } catch (const pdd::input_error&) {
  } catch (const pdd::geometry_error&) {
  } catch (const pdd::internal_error&) {
    throw;
  } catch (const pdd::error&) { // the .node sibling cannot be read
  }
  return std::nullopt;
}

/// The total length of the input segments.
double perimeter(const pdd::pslg& g) {
  double p = 0.0;
  for (const pdd::segment& s : g.segments)
    p += std::hypot(g.vertices[s.b].x - g.vertices[s.a].x, g.vertices[s.b].y - g.vertices[s.a].y);
  return p;
}

/// Distance of q from the closed segment [a, b] (rounded; only a size estimate).
double segment_distance(const pdd::point& q, const pdd::point& a, const pdd::point& b) {
  const double ux = b.x - a.x, uy = b.y - a.y;
  const double t =
      std::clamp(((q.x - a.x) * ux + (q.y - a.y) * uy) / (ux * ux + uy * uy), 0.0, 1.0);
  return std::hypot(q.x - (a.x + t * ux), q.y - (a.y + t * uy));
}

/// A lower bound on lfs_min of a general domain (see the file comment): the smallest distance
/// between two vertices, or a vertex and a segment not incident to it, over the whole PSLG.
/// Complexity O(V^2 + V S): at most 256 vertices and the segments of 8 KiB of text.
double general_lfs_lower_bound(const pdd::pslg& g) {
  double best = std::numeric_limits<double>::infinity();
  for (pdd::index_t v = 0; v < g.vertices.size(); ++v) {
    const pdd::point& q = g.vertices[v];
    for (pdd::index_t w = v + 1; w < g.vertices.size(); ++w)
      best = std::min(best, std::hypot(g.vertices[w].x - q.x, g.vertices[w].y - q.y));
    for (const pdd::segment& s : g.segments)
      if (s.a != v && s.b != v)
        best = std::min(best, segment_distance(q, g.vertices[s.a], g.vertices[s.b]));
  }
  return best;
}

/// The smallest angle in degrees between two segments of g at a shared vertex (180 if none).
double smallest_segment_angle_deg(const pdd::pslg& g) {
  std::vector<std::vector<pdd::index_t>> around(g.vertices.size());
  for (const pdd::segment& s : g.segments) {
    around[s.a].push_back(s.b);
    around[s.b].push_back(s.a);
  }
  double best = 180.0;
  for (pdd::index_t v = 0; v < g.vertices.size(); ++v)
    for (std::size_t i = 0; i < around[v].size(); ++i)
      for (std::size_t j = i + 1; j < around[v].size(); ++j) {
        const pdd::point &o = g.vertices[v], &p = g.vertices[around[v][i]],
                         &q = g.vertices[around[v][j]];
        const double ux = p.x - o.x, uy = p.y - o.y, wx = q.x - o.x, wy = q.y - o.y;
        const double a = std::abs(std::atan2(ux * wy - uy * wx, ux * wx + uy * wy));
        best = std::min(best, a * 180.0 / std::numbers::pi);
      }
  return best;
}

/// The FNV-1a hash of the bytes: the source of the choices that are not in the .poly.
std::uint64_t input_hash(const std::uint8_t* data, std::size_t size) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i)
    h = (h ^ data[i]) * 1099511628211ull;
  return h;
}

/// The divisor d in [8, 4096] of the area bound for these bytes (log-uniform in the hash).
double area_divisor(const std::uint8_t* data, std::size_t size) {
  return std::exp2(3.0 + 9.0 * static_cast<double>(input_hash(data, size) >> 11) * 0x1.0p-53);
}

/// Whether these bytes are meshed under the diametral lens (pdd::segment_encroachment), for
/// half the inputs (a bit of the hash the area divisor does not use).
bool under_diametral_lens(const std::uint8_t* data, std::size_t size) {
  return (input_hash(data, size) & 1u) != 0;
}

/// The mesh criteria for d (A = area / divisor, 20.7 deg), or nothing when the quality mesh of
/// d may be too large for a fuzzing input (see the limits in the file comment).
std::optional<pdd::mesh_criteria> small_mesh_criteria(const fuzz_domain& d, double divisor) {
  const pdd::pslg g = d.as_meshed();
  pdd::mesh_criteria c;
  c.max_area = pdd::domain_area(g) / divisor;
  if (!std::isnormal(c.max_area)) return std::nullopt;
  const double ratio =
      d.general ? 2.0 * perimeter(g) / general_lfs_lower_bound(g) : perimeter(g) / pdd::lfs_min(g);
  if (!(ratio <= max_perimeter_over_lfs)) return std::nullopt;
  return c;
}

/// Verifies a mesh of d as a library user does: pdd::verify on the PSLG given to generate, with
/// its default options (the faces as generate reads them and pdd's one rule for the triangles
/// exempt from the angle bound: shielded corners, or on a general domain cluster triangles), so
/// that this target and pdd-mesh --verify can never drift apart.
void check_mesh(const pdd::triangle_mesh& m, const fuzz_domain& d, const pdd::mesh_criteria& c,
                std::size_t n) {
  const pdd::verification_report rep = pdd::verify(m, d.input, {.criteria = c});
  if (rep.ok()) return;
  std::string what = "N = " + std::to_string(n) + (d.general ? " (general domain)" : "") +
                     ", max_area " + std::to_string(c.max_area) + ": the mesh fails verification:";
  for (const std::string& line : rep.messages)
    what += "\n  " + line;
  if (!rep.area_ok)
    what += "\n  mesh area " + std::to_string(rep.area_mesh) + " vs domain area " +
            std::to_string(rep.area_domain);
  finding(what);
}

/// True for the CGAL kernel's documented refusal of a general domain with two segments at a
/// sub-degree angle (see the file comment).
bool unresolvable_angle_refusal(const pdd::unresolvable_input_error& e, const fuzz_domain& d) {
  const std::string what = e.what();
  return d.general &&
         what.find("cannot be split: its rounded split point falls beyond a neighbouring "
                   "segment") != std::string::npos &&
         smallest_segment_angle_deg(d.input) < unresolvable_angle_deg;
}

/// Counts a refusal of one of the documented classes; any other is a finding.
void count_documented_refusal(const char* type, const std::string& what, std::size_t n) {
  for (const documented_refusal& r : documented_refusals)
    if (std::string_view(type) == r.type && what.find(r.message) != std::string::npos) {
      ++refusal_tally[refusal_key(type, what)];
      return;
    }
  finding("N = " + std::to_string(n) + ": generate() refused a validated input with an " +
          "undocumented " + type + ": " + what);
}

/// Meshes d with N subdomains; documented refusals are passes, anything else a finding.
void mesh_and_check(const fuzz_domain& d, const pdd::mesh_criteria& c, std::size_t n) {
  pdd::generate_options o;
  o.criteria = c;
  o.subdomains = n;
  o.threads = static_cast<unsigned>(n); // N = 2 runs both subdomains at once
  std::optional<pdd::generate_result> r;
  try {
    r = pdd::generate(d.input, o);
  } catch (const pdd::geometry_error& e) {
    count_documented_refusal("geometry_error", e.what(), n);
  } catch (const pdd::decomposition_error& e) {
    count_documented_refusal("decomposition_error", e.what(), n);
  } catch (const pdd::unresolvable_input_error& e) {
    if (n != 1 || !unresolvable_angle_refusal(e, d))
      finding("N = " + std::to_string(n) + ": " + e.what());
    ++counts.angle_refusals;
    return;
  } catch (const std::exception& e) {
    finding("N = " + std::to_string(n) + ": " + e.what());
  }
  if (!r) {
    ++(n == 1 ? counts.refused : counts.n2_refused)[d.general];
    return;
  }
  check_mesh(r->mesh, d, c, n);
  ++(n == 1 ? counts.verified : counts.n2_verified)[d.general];
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::atexit(report_outcomes);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > max_input_bytes) return 0;
  ++counts.inputs;
  try {
    const std::optional<fuzz_domain> d = read_domain(data, size);
    if (!d) {
      ++counts.refused_input;
      return 0;
    }
    const std::optional<pdd::mesh_criteria> c = small_mesh_criteria(*d, area_divisor(data, size));
    if (!c) {
      ++counts.skipped[d->general];
      return 0;
    }
    pdd::mesh_criteria criteria = *c;
    if (under_diametral_lens(data, size)) // half the inputs: Triangle's rule for -q without -D
      criteria.encroachment = pdd::segment_encroachment::diametral_lens;
    mesh_and_check(*d, criteria, 1);
    mesh_and_check(*d, criteria, 2);
  } catch (const std::exception& e) {
    finding(std::string("unexpected exception: ") + e.what());
  }
  return 0;
}
