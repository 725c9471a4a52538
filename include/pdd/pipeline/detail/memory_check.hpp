/// \file memory_check.hpp
/// Implementation of pdd::pipeline::check_memory: the estimate against physical memory and
/// 32-bit indices.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/errors.hpp>
#include <pdd/pipeline/planning.hpp>
#include <pdd/pipeline/system.hpp>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>

namespace pdd::detail {

/// \throws pdd::limit_error when the estimate exceeds 90% of physical memory, or a mesh kept in
/// memory would exceed 32-bit indices.
inline void check_memory_plan(double triangles, std::size_t subdomains, unsigned threads,
                              bool retains_meshes, double max_area) {
  if (!std::isfinite(triangles)) return;
  const auto gib = [](double b) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f GiB", b / 1073741824.0);
    return std::string(buf);
  };
  const std::string what = "max_area " + std::to_string(max_area) + " gives about " +
                           std::to_string(static_cast<long long>(triangles)) + " triangles";
  if (retains_meshes && triangles / 2.0 * 1.05 >= static_cast<double>(no_index))
    throw limit_error(what + ": more vertices than 32-bit indices allow in one mesh; use a "
                             "file sink (vtu_directory_sink) or a larger max_area");
  const double need = estimate_peak_bytes(triangles, subdomains, threads, retains_meshes);
  const double have = static_cast<double>(physical_memory_bytes());
  if (have > 0.0 && need > 0.9 * have)
    throw limit_error(what + ", needing about " + gib(need) + " of memory at the peak (" +
                      std::to_string(subdomains) + " subdomains, " + std::to_string(threads) +
                      " threads" + (retains_meshes ? ", kept in memory" : "") +
                      "); the machine has " + gib(have) +
                      (retains_meshes ? ". Use a file sink (vtu_directory_sink)," : ". Use") +
                      " more subdomains or a larger max_area");
}

} // namespace pdd::detail
