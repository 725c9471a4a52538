/// \file memory_check.hpp
/// Implementation of pdd::pipeline::check_memory: the up-front refusal of a run whose estimate
/// (pdd::estimate_mesh_size) exceeds the user's triangle limit, physical memory or 32-bit
/// indices, with the estimate, the feature that causes it and the memory it would need.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/pipeline/planning.hpp>
#include <pdd/pipeline/system.hpp>
#include <pdd/sizing/mesh_size_estimate.hpp>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>

namespace pdd::detail {

/// What the size check looks at.
struct size_plan {
  double triangles = 0.0;                       ///< planned triangles (estimate + split points)
  const mesh_size_estimate* estimate = nullptr; ///< where the estimate comes from
  const pslg* domain = nullptr;
  std::size_t subdomains = 1;
  unsigned threads = 1;
  bool retains_meshes = true;
  std::size_t max_triangles = 0; ///< the user's limit (0: physical memory decides)
  bool check_memory = true;      ///< generate_options::check_memory
};

/// printf-style formatting into a std::string (short messages).
template <class... A>
std::string format(const char* f, A... a) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a...);
  return buf;
}

/// "vertex 3 (x, y)" or "segment 4 (vertices 1-2)".
inline std::string describe_feature(const pslg& g, pslg_feature f) {
  if (f.type == pslg_feature::kind::vertex)
    return format("vertex %u (%.6g, %.6g)", f.id, g.vertices[f.id].x, g.vertices[f.id].y);
  return format("segment %u (vertices %u-%u)", f.id, g.segments[f.id].a, g.segments[f.id].b);
}

/// The estimate and the feature that costs the most, in words.
inline std::string describe_estimate(const pslg& g, const mesh_size_estimate& e) {
  std::string s = format("the mesh would have about %.3g triangles (%.3g by the area bound alone)",
                         e.triangles, e.area_triangles);
  if (e.cause.first.id == no_index || !(e.cause_triangles > 0.0)) return s;
  const feature_pair& p = e.cause;
  s += "; the local feature size adds " + format("%.3g", e.cause_triangles) + " of them at ";
  if (p.apex != no_index)
    s += format("the angle of %.3g deg at vertex %u (%.6g, %.6g) between segments %u and %u",
                e.cause_angle_deg, p.apex, g.vertices[p.apex].x, g.vertices[p.apex].y, p.first.id,
                p.second.id);
  else
    s += describe_feature(g, p.first) + " and " + describe_feature(g, p.second);
  s += format(": near (%.6g, %.6g) the features are %.3g apart", e.cause_location.x,
              e.cause_location.y, e.cause_gap);
  if (std::isfinite(e.cause_bound)) s += format(" where the area bound is %.3g", e.cause_bound);
  return s;
}

inline std::string gib(double bytes) {
  return format("%.3g GiB", bytes / 1073741824.0);
}

/// \throws pdd::limit_error when the planned triangles exceed p.max_triangles (when set), or
/// else (with p.check_memory) when the peak memory estimate exceeds 90% of physical memory;
/// and when a mesh kept in memory would exceed 32-bit indices. The message has the estimate,
/// its cause (describe_estimate) and the memory the run would need.
inline void check_size_plan(const size_plan& p) {
  if (!std::isfinite(p.triangles)) return;
  const double need = estimate_peak_bytes(p.triangles, p.subdomains, p.threads, p.retains_meshes);
  const std::string what = describe_estimate(*p.domain, *p.estimate) +
                           format(". It would need about %s of memory at the peak (%zu "
                                  "subdomains, %u threads%s)",
                                  gib(need).c_str(), p.subdomains, p.threads,
                                  p.retains_meshes ? ", kept in memory" : "");
  if (p.max_triangles > 0) {
    if (p.triangles > static_cast<double>(p.max_triangles))
      throw limit_error(what + format("; more than the limit of %zu triangles (max_triangles). "
                                      "Use a larger max_triangles, a larger max_area or a "
                                      "simpler domain",
                                      p.max_triangles));
  } else if (p.check_memory) {
    const double have = static_cast<double>(physical_memory_bytes());
    if (have > 0.0 && need > 0.9 * have)
      throw limit_error(what + "; the machine has " + gib(have) +
                        (p.retains_meshes ? ". Use a file sink (vtu_directory_sink)," : ". Use") +
                        " more subdomains, a larger max_area or a simpler domain (max_triangles "
                        "sets the limit instead of memory)");
  }
  if (p.retains_meshes && p.triangles / 2.0 * 1.05 >= static_cast<double>(no_index))
    throw limit_error(what + "; more vertices than 32-bit indices allow in one mesh. Use a file "
                             "sink (vtu_directory_sink) or a larger max_area");
}

} // namespace pdd::detail
