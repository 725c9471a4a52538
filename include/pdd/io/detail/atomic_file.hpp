/// \file atomic_file.hpp
/// Implementation of pdd::write_file_atomically: the temporary file's name, opening,
/// finishing, discarding and renaming it, and the writes in place into special files.
#pragma once

#include <pdd/errors.hpp>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <ios>
#include <ostream>
#include <random>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

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

/// fsync of the file or directory at p (POSIX), so that what was written survives a power loss
/// or a crash of the system: a file's data before it is renamed into place, a directory's entry
/// after. A directory whose file system cannot sync directories (EINVAL) is accepted.
/// \throws pdd::error starting with `where` when p cannot be opened or the sync fails (EIO,
///   ENOSPC on delayed allocation).
inline void sync_to_disk(const std::filesystem::path& p, bool directory, const std::string& where) {
  const int fd = ::open(p.c_str(), O_RDONLY | O_CLOEXEC | (directory ? O_DIRECTORY : 0));
  if (fd < 0)
    throw error(where + "cannot open " + (directory ? "its directory" : "the written file") +
                " to sync it (" + errno_message(errno) + ")");
  const int rc = ::fsync(fd);
  const int e = errno;
  ::close(fd);
  if (rc != 0 && !(directory && e == EINVAL))
    throw error(where + "syncing " + (directory ? "its directory" : "the file") +
                " to disk failed (" + errno_message(e) + ")");
}

/// The directory that holds path (".", for a bare file name).
inline std::filesystem::path directory_of(const std::filesystem::path& path) {
  return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
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

/// Syncs the complete temporary file, renames it onto path (atomic on POSIX file systems) and
/// syncs the directory, so that after a crash path holds either its old content or the new one,
/// never an empty or torn file. \throws pdd::error starting with `where` when the sync or the
/// rename fails (the temporary is removed) or the directory's sync fails (path is complete).
inline void rename_temporary(const std::filesystem::path& tmp, const std::filesystem::path& path,
                             const std::string& where) {
  std::error_code ec;
  try {
    sync_to_disk(tmp, false, where);
  } catch (const error&) {
    std::filesystem::remove(tmp, ec);
    throw;
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw error(where + "renaming the temporary file failed (" + ec.message() + ")");
  }
  sync_to_disk(directory_of(path), true, where);
}

/// True when path exists and is, or links to, neither a regular file nor a directory: a
/// character or block device (/dev/null), a FIFO, a socket, /dev/stdout's pipe or terminal.
inline bool is_special_file(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(st)) return false;
  return !std::filesystem::is_regular_file(st) && !std::filesystem::is_directory(st);
}

/// Writes `writer`'s output straight into the special file at path (no temporary, no rename,
/// no fsync: a device or a pipe has no file to make durable).
/// 	hrows pdd::error starting with `where` when it cannot be opened or a write fails; a
///   pdd::error from `writer` unchanged, any other std::exception as a pdd::error.
template <class Writer>
void write_in_place(const std::filesystem::path& path, Writer& writer, const std::string& where) {
  std::ofstream out;
  errno = 0;
  out.open(path, std::ios::binary);
  if (!out.is_open()) throw error(where + "cannot open it (" + errno_message(errno) + ")");
  try {
    writer(static_cast<std::ostream&>(out));
  } catch (const error&) {
    throw;
  } catch (const std::exception& e) {
    throw error(where + e.what());
  }
  finish_temporary(out, where);
}

} // namespace pdd::detail
