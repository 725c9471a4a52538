/// \file system.hpp
/// Small operating-system queries used by the drivers and the pipeline (Linux/POSIX).
#pragma once

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstddef>

namespace pdd {

/// Peak resident set size of this process so far, in MiB (getrusage; 0 if unavailable).
inline double peak_rss_mib() {
  rusage ru{};
  if (getrusage(RUSAGE_SELF, &ru) != 0) return 0.0;
  return static_cast<double>(ru.ru_maxrss) / 1024.0; // ru_maxrss is in KiB on Linux
}

/// CPU time (user + system) this process has used so far, in seconds.
inline double cpu_seconds() {
  rusage ru{};
  if (getrusage(RUSAGE_SELF, &ru) != 0) return 0.0;
  const auto s = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * t.tv_usec; };
  return s(ru.ru_utime) + s(ru.ru_stime);
}

/// Physical memory of the machine in bytes (0 if unknown).
inline std::size_t physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page = sysconf(_SC_PAGE_SIZE);
  return (pages > 0 && page > 0) ? static_cast<std::size_t>(pages) * static_cast<std::size_t>(page)
                                 : 0;
}

/// True when standard error is a terminal (progress lines are drawn only then).
inline bool stderr_is_terminal() {
  return isatty(STDERR_FILENO) == 1;
}

/// Seconds elapsed since a steady_clock time point.
inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace pdd
