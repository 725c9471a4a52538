/// \file madd_start.hpp
/// pdd::madd_start: the regions pdd::decompose starts from, found once: the connected
/// components of a domain of closed loops, or the faces of a general PSLG (issue 13), with
/// caps where a small angle lies on a segment between two of them. A caller that decomposes one
/// domain several times (the pipeline's plan and its decomposition, Algorithm 7.1's rounds of the
/// geometric path) builds the domain's triangulation once instead of at every call.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/madd/detail/assemble.hpp>
#include <pdd/madd/detail/face_regions.hpp>
#include <pdd/madd/detail/region.hpp>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// The regions MADD starts from for one domain (see pdd::decompose).
class madd_start {
public:
  /// Validates g (pdd::validate) and finds its regions on the triangulation validation builds.
  /// \throws pdd::geometry_error as pdd::validate, or as pdd::domain_faces for a general PSLG
  /// whose g.rule is not Triangle's (faces by odd nesting need closed loops).
  /// Complexity O(n log^2 n). Thread-safety: reentrant.
  explicit madd_start(const pslg& g)
      : madd_start(g, domain_faces(g, domain_faces::validate_first{})) {}

  /// From g's faces already found: domain_faces(g, validate_first), or domain_faces(g) for a
  /// domain of closed loops. \pre g is valid. \throws as above. Complexity O(n log n).
  madd_start(const pslg& g, const domain_faces& faces) {
    if (const loop_structure* loops = faces.loops()) {
      regions_ = detail::regions_of(g, *loops);
      return;
    }
    general_ = true;
    detail::face_region_set f =
        g.rule == domain_rule::triangle ? detail::face_regions(g, faces) : detail::face_regions(g);
    regions_ = std::move(f.regions);
    cap_reason_ = std::move(f.cap_reason);
  }

  /// True for a domain that is not one of closed loops (MADD starts from its faces).
  bool general() const noexcept { return general_; }
  /// The regions MADD starts from: one per connected component of a domain of closed loops,
  /// one per face of a general PSLG, less its caps, and one per cap (detail::cap_corners).
  const std::vector<detail::madd_region>& regions() const noexcept { return regions_; }
  /// Empty unless a general PSLG got caps at small angles between its faces; then how many
  /// and why (pdd::face_decoupling_report::cap_reason).
  const std::string& cap_reason() const noexcept { return cap_reason_; }

private:
  std::vector<detail::madd_region> regions_;
  std::string cap_reason_;
  bool general_ = false;
};

} // namespace pdd
