/// \file atomic_file.hpp
/// Implementation of pdd::write_file_atomically: the temporary file's name, opening,
/// finishing, discarding and renaming it.
#pragma once

#include <pdd/errors.hpp>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <ios>
#include <random>
#include <string>
#include <system_error>

namespace pdd::detail {

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
  // Appended piece by piece: GCC 12's "." + std::string inlines into a false
  // -Wstringop-overflow (GCC bug 105329) in some translation units.
  std::string name(1, '.');
  name.append(target.filename().string()).append(".pdd-tmp-").append(digits);
  return target.parent_path() / name;
}

inline std::string errno_message(int e) {
  return e != 0 ? std::generic_category().message(e) : std::string("unknown reason");
}

/// Opens the temporary file tmp for writing (binary, truncated).
/// \throws pdd::error starting with `where` when it cannot be created.
inline std::ofstream open_temporary(const std::filesystem::path& tmp, const std::string& where) {
  std::ofstream out;
  errno = 0;
  out.open(tmp, std::ios::binary | std::ios::trunc);
  if (!out.is_open())
    throw error(where + "cannot create a temporary file there (" + errno_message(errno) + ")");
  return out;
}

/// Flushes, checks and closes the written temporary file.
/// \throws pdd::error starting with `where` when a write or the close failed.
inline void finish_temporary(std::ofstream& out, const std::string& where) {
  out.flush();
  if (!out) throw error(where + "write failed (" + errno_message(errno) + ")");
  out.close();
  if (out.fail()) throw error(where + "closing the file failed");
}

/// Closes and removes the temporary file after a failure; never throws.
inline void discard_temporary(std::ofstream& out, const std::filesystem::path& tmp) noexcept {
  try {
    out.close();
  } catch (...) {
  }
  std::error_code ec;
  std::filesystem::remove(tmp, ec);
}

/// Renames the complete temporary file onto path (atomic on POSIX file systems).
/// \throws pdd::error starting with `where` when the rename fails (the temporary is removed).
inline void rename_temporary(const std::filesystem::path& tmp, const std::filesystem::path& path,
                             const std::string& where) {
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw error(where + "renaming the temporary file failed (" + ec.message() + ")");
  }
}

} // namespace pdd::detail
