/// \file atomic_file.hpp
/// pdd::write_file_atomically: every pdd writer goes through it, so a reader never sees a
/// half-written file and a failed write leaves neither a partial output nor a temporary file.
#pragma once

#include <pdd/errors.hpp>

#include <atomic>
#include <cerrno>
#include <concepts>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <random>
#include <string>
#include <system_error>
#include <utility>

namespace pdd {

namespace detail {

/// A fresh name in the directory of `target`: ".<name>.pdd-tmp-<16 hex digits>". The digits mix a
/// per-process random salt with a process-wide counter, so concurrent writers (threads or
/// processes) never share a temporary file.
inline std::filesystem::path temporary_sibling(const std::filesystem::path& target) {
  static const std::uint64_t salt = [] {
    std::random_device rd;
    return (static_cast<std::uint64_t>(rd()) << 32) ^ rd();
  }();
  static std::atomic<std::uint64_t> counter{0};
  std::uint64_t x = salt ^ (counter.fetch_add(1) * 0x9e3779b97f4a7c15ULL);
  x ^= x >> 31; // spread the counter's bits over all digits
  static constexpr char hex[] = "0123456789abcdef";
  std::string digits(16, '0');
  for (int i = 15; i >= 0; --i, x >>= 4)
    digits[static_cast<std::size_t>(i)] = hex[x & 15];
  return target.parent_path() / ("." + target.filename().string() + ".pdd-tmp-" + digits);
}

inline std::string errno_message(int e) {
  return e != 0 ? std::generic_category().message(e) : std::string("unknown reason");
}

} // namespace detail

/// Writes a file atomically: `writer(os)` writes the whole content to a temporary file in the
/// same directory as `path`; the stream is flushed, closed and checked, and only then renamed
/// onto `path` (std::filesystem::rename, atomic on POSIX file systems). An existing file at
/// `path` is replaced only on success.
///
/// \tparam Writer callable as `writer(std::ostream&)`; it may throw.
/// \pre `path` names a file (not a directory) in an existing directory.
/// \throws pdd::error naming `path` when the temporary file cannot be created, a write fails
///   (stream state bad/fail), or the rename fails; a pdd::error thrown by `writer` is rethrown
///   unchanged and any other std::exception is rethrown as pdd::error with the path. In every
///   failure case the temporary file is removed and `path` is untouched.
/// Complexity: linear in the bytes written. Thread-safety: safe for distinct paths; concurrent
///   writes of the same path leave one complete version.
template <class Writer>
requires std::invocable<Writer&, std::ostream&>
void write_file_atomically(const std::filesystem::path& path, Writer&& writer) {
  namespace fs = std::filesystem;
  const std::string where = "cannot write '" + path.string() + "': ";
  if (path.empty() || !path.has_filename()) throw error(where + "not a file name");
  const fs::path tmp = detail::temporary_sibling(path);

  std::ofstream out;
  errno = 0;
  out.open(tmp, std::ios::binary | std::ios::trunc);
  if (!out.is_open())
    throw error(where + "cannot create a temporary file there (" + detail::errno_message(errno) +
                ")");

  const auto discard = [&]() noexcept {
    try {
      out.close();
    } catch (...) {
    }
    std::error_code ec;
    fs::remove(tmp, ec);
  };
  try {
    writer(static_cast<std::ostream&>(out));
    out.flush();
    if (!out) throw error(where + "write failed (" + detail::errno_message(errno) + ")");
    out.close();
    if (out.fail()) throw error(where + "closing the file failed");
  } catch (const error&) {
    discard();
    throw;
  } catch (const std::exception& e) {
    discard();
    throw error(where + e.what());
  } catch (...) {
    discard();
    throw;
  }

  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw error(where + "renaming the temporary file failed (" + ec.message() + ")");
  }
}

} // namespace pdd
