/// \file atomic_file.hpp
/// pdd::write_file_atomically: every pdd writer goes through it, so a reader never sees a
/// half-written file and a failed write leaves neither a partial output nor a temporary file.
#pragma once

#include <pdd/errors.hpp>
#include <pdd/io/detail/atomic_file.hpp>

#include <concepts>
#include <exception>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>

namespace pdd {

/// Writes a file atomically and durably: `writer(os)` writes the whole content to a temporary
/// file in the same directory as `path`; the stream is flushed, closed and checked, the file
/// synced to disk (fsync), and only then renamed onto `path` (std::filesystem::rename, atomic on
/// POSIX file systems), and the directory synced: a run killed at any moment, or a power loss,
/// leaves either no file (or the old one) or the complete new one under `path`. An existing
/// file at `path` is replaced only on success. A `path` that is, or links to, something other
/// than a regular file or a directory (a character device such as /dev/null, a FIFO, a socket,
/// /dev/stdout) is written in place, as a shell redirection would: renaming a file onto it
/// would replace /dev/null with a regular file for every other program on the machine.
///
/// \tparam Writer callable as `writer(std::ostream&)`; it may throw.
/// \pre `path` names a file (not a directory) in an existing directory.
/// \throws pdd::error naming `path` when the temporary file cannot be created, a write fails
///   (stream state bad/fail, e.g. a full file system), the sync or the rename fails; a pdd::error
///   thrown by `writer` is rethrown unchanged and any other std::exception is rethrown as
///   pdd::error with the path. In every failure case the temporary file is removed and `path` is
///   untouched.
/// Complexity: linear in the bytes written. Thread-safety: safe for distinct paths; concurrent
///   writes of the same path leave one complete version.
template <class Writer>
requires std::invocable<Writer&, std::ostream&>
void write_file_atomically(const std::filesystem::path& path, Writer&& writer) {
  const std::string where = "cannot write '" + path.string() + "': ";
  if (path.empty() || !path.has_filename()) throw error(where + "not a file name");
  if (detail::is_special_file(path)) {
    detail::write_in_place(path, writer, where);
    return;
  }
  const std::filesystem::path tmp = detail::temporary_sibling(path);
  std::ofstream out = detail::open_temporary(tmp, where);
  try {
    writer(static_cast<std::ostream&>(out));
    detail::finish_temporary(out, where);
  } catch (const error&) {
    detail::discard_temporary(out, tmp);
    throw;
  } catch (const std::exception& e) {
    detail::discard_temporary(out, tmp);
    throw error(where + e.what());
  } catch (...) {
    detail::discard_temporary(out, tmp);
    throw;
  }
  detail::rename_temporary(tmp, path, where);
}

} // namespace pdd
