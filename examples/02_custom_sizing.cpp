// Example 2: a custom SizingField: small triangles near a point, large ones far away.
#include <pdd/concepts/sizing_field.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/kernels/default_mesher.hpp>
// the kernel compiled for a field of our own (libpdd holds it for pdd::any_sizing and
// pdd::uniform_sizing only)
#include <pdd/kernels/default_mesher_templates.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/verify.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

// Any copyable type with a thread-safe `double area_at(pdd::point) const` models SizingField.
struct point_source {
  pdd::point centre;
  double near_area; // area bound at the centre
  double far_area;  // area bound far away
  double area_at(const pdd::point& p) const {
    const double d = std::hypot(p.x - centre.x, p.y - centre.y);
    return std::min(far_area, near_area + 0.02 * d * d);
  }
};
static_assert(pdd::SizingField<point_source>);

int main() {
  const pdd::pslg pipe = pdd::pipe_domain();
  const point_source sizing{{0.75, 0.0}, 2e-5, 2e-3};
  const pdd::mesh_criteria criteria; // 20.7 degrees
  const auto result = pdd::default_mesher{}.mesh(pipe, criteria, sizing);
  const auto st = pdd::compute_statistics(result.mesh, sizing);
  const auto report =
      pdd::verify(result.mesh, pipe, pdd::verify_options{.criteria = criteria}, sizing);
  std::printf("%zu triangles, min angle %.2f deg, max area / bound %.3f, verified: %s\n",
              st.triangles, st.min_angle_deg, st.max_area_ratio, report.ok() ? "yes" : "NO");
  return report.ok() && st.max_area_ratio <= 1.0 ? 0 : 1;
}
