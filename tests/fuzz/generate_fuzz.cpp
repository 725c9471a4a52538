// libFuzzer target over the whole user path of pdd-mesh: the bytes are read as a Triangle .poly
// (pdd::parse_poly from memory), validated, meshed by pdd::generate with N = 1 and N = 2, and
// every mesh is checked by pdd::verify: exact Delaunay, orientation, conformity to the input
// segments, the domain area covered, the area bound, and the angle bound on every triangle that
// is not a shielded corner (dissertation 8.1).
//
// Refusals of bad input are passes: pdd::input_error (parser), pdd::geometry_error (validate,
// shields), pdd::decomposition_error (MADD cannot split the domain as asked), pdd::limit_error,
// and pdd::error from the parser (a .poly with 0 vertices names a .node file that cannot be
// read). Everything else aborts, and libFuzzer keeps the input: any other exception
// (internal_error, meshing_error, decoupling_error, std::exception), a crash, a sanitizer report,
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
// lfs_min; the shields cut them off): a triangle of base 1, height 1317 and a 0.04 deg apex
// (P / lfs_min = 2635) took 24 s under ASan on a loaded machine, hence -timeout=300.
#include <pdd/errors.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/lfs.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/shielding/shield_statistics.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <sstream>
#include <string>

namespace {

constexpr std::size_t max_input_bytes = 8192;
constexpr std::size_t max_vertices = 256;
constexpr double max_perimeter_over_lfs = 20000.0;

/// Reports a finding and aborts (libFuzzer then saves the input as crash-<hash>).
[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "pdd fuzz finding: %s\n", what.c_str());
  std::abort();
}

/// The parsed and validated domain, or nothing when the parser or validate() refuses it.
std::optional<pdd::pslg> read_domain(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    // A vertex count of 0 refers to a .node sibling: looked up under /dev/null, never found.
    pdd::pslg g = pdd::parse_poly(in, "fuzz.poly", "/dev/null");
    if (g.vertices.size() > max_vertices) return std::nullopt;
    // domains not made of closed loops are meshed whole (issue 13); this target fuzzes the
    // decoupled pipeline
    if (!pdd::has_closed_loops(g)) return std::nullopt;
    return g;
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

/// The divisor d in [8, 4096] of the area bound for these bytes (FNV-1a hash, log-uniform).
double area_divisor(const std::uint8_t* data, std::size_t size) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < size; ++i)
    h = (h ^ data[i]) * 1099511628211ull;
  return std::exp2(3.0 + 9.0 * static_cast<double>(h >> 11) * 0x1.0p-53);
}

/// The mesh criteria for g (A = area / divisor, 20.7 deg), or nothing when the quality mesh of
/// g may be too large for a fuzzing input (see the limits above).
std::optional<pdd::mesh_criteria> small_mesh_criteria(const pdd::pslg& g, double divisor) {
  pdd::mesh_criteria c;
  c.max_area = pdd::domain_area(g) / divisor;
  if (!std::isnormal(c.max_area)) return std::nullopt;
  const double ratio = perimeter(g) / pdd::lfs_min(g);
  if (!(ratio <= max_perimeter_over_lfs)) return std::nullopt;
  return c;
}

/// Verifies a mesh of g (shielded corners exempt from the angle bound only).
void check_mesh(const pdd::triangle_mesh& m, const pdd::pslg& g, const pdd::mesh_criteria& c,
                std::size_t n) {
  pdd::verify_options vo{.criteria = c};
  vo.quality_exempt = pdd::find_shielded_triangles(m, g);
  const pdd::verification_report rep = pdd::verify(m, g, vo);
  if (rep.ok()) return;
  std::string what = "N = " + std::to_string(n) + ", max_area " + std::to_string(c.max_area) +
                     ": the mesh fails verification:";
  for (const std::string& line : rep.messages)
    what += "\n  " + line;
  if (!rep.area_ok)
    what += "\n  mesh area " + std::to_string(rep.area_mesh) + " vs domain area " +
            std::to_string(rep.area_domain);
  finding(what);
}

/// Meshes g with N subdomains; refusals of the input are passes, anything else a finding.
void mesh_and_check(const pdd::pslg& g, const pdd::mesh_criteria& c, std::size_t n) {
  pdd::generate_options o;
  o.criteria = c;
  o.subdomains = n;
  o.threads = static_cast<unsigned>(n); // N = 2 runs both subdomains at once
  std::optional<pdd::generate_result> r;
  try {
    r = pdd::generate(g, o);
  } catch (const pdd::geometry_error&) {
    return;
  } catch (const pdd::decomposition_error&) {
    return;
  } catch (const pdd::limit_error&) {
    return;
  } catch (const std::exception& e) {
    finding("N = " + std::to_string(n) + ": " + e.what());
  }
  check_mesh(r->mesh, g, c, n);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > max_input_bytes) return 0;
  try {
    const std::optional<pdd::pslg> g = read_domain(data, size);
    if (!g) return 0;
    const std::optional<pdd::mesh_criteria> c = small_mesh_criteria(*g, area_divisor(data, size));
    if (!c) return 0;
    mesh_and_check(*g, *c, 1);
    mesh_and_check(*g, *c, 2);
  } catch (const std::exception& e) {
    finding(std::string("unexpected exception: ") + e.what());
  }
  return 0;
}
