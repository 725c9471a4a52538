// Example 1: mesh a polygon with holes with the default kernel (CGAL's; the native one in a
// PDD_PERMISSIVE build) and check the result.
#include <pdd/geometry/validate.hpp>
#include <pdd/kernels/default_mesher.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/verify.hpp>

#include <array>
#include <cstdio>

int main() {
  pdd::pslg domain;
  // Outer square (counter-clockwise, marker 1) and two square holes (marker 2 and 3).
  domain.add_loop(std::array<pdd::point, 4>{{{0, 0}, {4, 0}, {4, 3}, {0, 3}}}, 1);
  domain.add_loop(std::array<pdd::point, 4>{{{1, 1}, {1, 2}, {1.5, 2}, {1.5, 1}}}, 2);
  domain.add_loop(std::array<pdd::point, 4>{{{2.5, 1}, {2.5, 2}, {3, 2}, {3, 1}}}, 3);
  domain.holes = {{1.25, 1.5}, {2.75, 1.5}};
  pdd::validate(domain); // throws pdd::geometry_error naming the offending ids

  const pdd::mesh_criteria criteria{.min_angle_deg = 25.0, .max_area = 0.01};
  const pdd::mesher_result result =
      pdd::default_mesher{}.mesh(domain, criteria, pdd::uniform_sizing{criteria.max_area});

  const pdd::mesh_statistics st = pdd::compute_statistics(result.mesh);
  const pdd::verification_report report =
      pdd::verify(result.mesh, domain, pdd::verify_options{.criteria = criteria});
  std::printf("%zu triangles, min angle %.2f deg, area %.6f (domain %.6f), verified: %s\n",
              st.triangles, st.min_angle_deg, report.area_mesh, report.area_domain,
              report.ok() ? "yes" : "NO");
  return report.ok() ? 0 : 1;
}
