/// \file domain_reading.hpp
/// The pipeline's first look at its domain: validated once (one constrained triangulation),
/// whether it is one of closed loops, its area, the plan's size estimate and MADD's regions.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/madd/madd_start.hpp>
#include <pdd/pipeline/detail/sizing_plan.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/sizing/mesh_size_estimate.hpp>

#include <optional>

namespace pdd::detail {

/// What read_domain found.
struct domain_reading {
  bool general = false;            ///< not one of closed loops (read by Triangle's rule)
  double area = 0.0;               ///< as pdd::domain_area
  mesh_size_estimate estimate;     ///< the plan's: estimate_faces or estimate_plan
  std::optional<madd_start> start; ///< MADD's regions, unless one subdomain is asked for
};

/// Validates `domain` (pdd::validate) and reads it on the one triangulation validation builds;
/// a domain that is not one of closed loops gets Triangle's rule (domain.rule).
/// `decoupling_area`: the smallest area bound (estimate_plan's shield area).
/// \throws pdd::geometry_error as pdd::validate. Complexity as pdd::validate, plus the estimate.
inline domain_reading read_domain(pslg& domain, const generate_options& o, double decoupling_area) {
  domain_reading r;
  const domain_faces faces(domain, domain_faces::validate_first{});
  r.general = !faces.closed_loops();
  if (r.general) domain.rule = domain_rule::triangle;
  if (o.subdomains != 1) r.start.emplace(domain, faces);
  r.area = faces.area();
  r.estimate = r.general ? estimate_faces(domain, faces, o.criteria, o.sizing)
                         : estimate_plan(domain, o.criteria, o.sizing, decoupling_area);
  return r;
}

} // namespace pdd::detail
