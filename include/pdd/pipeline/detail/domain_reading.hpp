/// \file domain_reading.hpp
/// The pipeline's first look at its domain: validated once (one constrained triangulation),
/// whether it is one of closed loops, its area, the plan's size estimate and MADD's regions.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/madd/madd_start.hpp>
#include <pdd/pipeline/detail/sizing_plan.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/sizing/domain_region.hpp>
#include <pdd/sizing/mesh_size_estimate.hpp>
#include <pdd/sizing/sizing_range.hpp>

#include <algorithm>
#include <limits>
#include <optional>

namespace pdd::detail {

/// What read_domain found.
struct domain_reading {
  bool general = false;            ///< not one of closed loops (read by Triangle's rule)
  double area = 0.0;               ///< as pdd::domain_area
  mesh_size_estimate estimate;     ///< the plan's: estimate_faces or estimate_plan
  std::optional<madd_start> start; ///< MADD's regions, unless one subdomain is asked for
  /// The lower bound of the user's field over the domain (pdd::sizing_range over its faces:
  /// the field is evaluated only in the domain); infinity without a field.
  double sizing_min = std::numeric_limits<double>::infinity();
};

/// Validates `domain` (pdd::validate) and reads it on the one triangulation validation builds;
/// a domain that is not one of closed loops gets Triangle's rule (domain.rule). The smallest
/// area bound, min(max_area, sizing_min), is estimate_plan's shield area.
/// \throws pdd::geometry_error as pdd::validate; pdd::sizing_error as pdd::sizing_range (a
/// field that is not positive somewhere in the domain, naming the point). Complexity as
/// pdd::validate, plus the field's bounds and the estimate.
inline domain_reading read_domain(pslg& domain, const generate_options& o) {
  domain_reading r;
  const domain_faces faces(domain, domain_faces::validate_first{});
  if (o.sizing)
    r.sizing_min =
        sizing_range(o.sizing, domain_region(domain.vertices, faces.triangles()).view()).lo;
  const double decoupling_area = std::min(o.criteria.max_area, r.sizing_min);
  r.general = !faces.closed_loops();
  if (r.general) domain.rule = domain_rule::triangle;
  if (o.subdomains != 1) r.start.emplace(domain, faces);
  r.area = faces.area();
  r.estimate = r.general ? estimate_faces(domain, faces, o.criteria, o.sizing)
                         : estimate_plan(domain, o.criteria, o.sizing, decoupling_area);
  return r;
}

} // namespace pdd::detail
