/// \file wire.hpp
/// Implementation of pdd::mpi: byte buffers of plain values, waiting on MPI without spinning a
/// core, gathering byte buffers from every rank, and pdd errors across ranks.
#pragma once

#include <pdd/errors.hpp>

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <exception>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace pdd::mpi::detail {

/// Throws pdd::internal_error when an MPI call did not return MPI_SUCCESS (only reached
/// with an error handler other than MPI_ERRORS_ARE_FATAL on the communicator).
inline void check(int rc, const char* call) {
  if (rc != MPI_SUCCESS) throw internal_error(std::string("MPI call failed: ") + call);
}

/// Appends trivially copyable values and strings to a byte buffer (the ranks run the same
/// binary: native byte order and layout).
struct byte_writer {
  std::string bytes;
  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void put_string(const std::string& s) {
    put(static_cast<std::uint64_t>(s.size()));
    bytes += s;
  }
};

/// Reads what a byte_writer wrote, in the same order. \throws pdd::internal_error past the end.
class byte_reader {
public:
  explicit byte_reader(const std::string& bytes) : bytes_(bytes) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T v;
    take(sizeof v);
    std::memcpy(&v, bytes_.data() + pos_ - sizeof v, sizeof v);
    return v;
  }
  std::string get_string() {
    const auto n = static_cast<std::size_t>(get<std::uint64_t>());
    take(n);
    return bytes_.substr(pos_ - n, n);
  }
  bool done() const noexcept { return pos_ == bytes_.size(); }

private:
  void take(std::size_t n) {
    if (bytes_.size() - pos_ < n) throw internal_error("pdd::mpi: truncated message");
    pos_ += n;
  }
  const std::string& bytes_;
  std::size_t pos_ = 0;
};

/// Sleeps between polls, 50 us growing to 2 ms while nothing happens: a waiting rank leaves
/// its core to the ranks that mesh (MPI's blocking calls spin, which halves the speed of an
/// oversubscribed node).
class backoff {
public:
  void idle() {
    std::this_thread::sleep_for(std::chrono::microseconds(us_));
    us_ = std::min(us_ * 2, 2000);
  }
  void progress() noexcept { us_ = 50; }

private:
  int us_ = 50;
};

/// Waits for `request` to complete, calling poll() between tests (poll returns whether it
/// did something) and sleeping when nothing happened.
template <class Poll>
void wait_politely(MPI_Request& request, Poll&& poll) {
  backoff pause;
  for (;;) {
    int done = 0;
    check(MPI_Test(&request, &done, MPI_STATUS_IGNORE), "MPI_Test");
    if (done) return;
    if (poll())
      pause.progress();
    else
      pause.idle();
  }
}

/// A barrier over comm that sleeps while it waits (see backoff).
inline void polite_barrier(MPI_Comm comm) {
  MPI_Request r;
  check(MPI_Ibarrier(comm, &r), "MPI_Ibarrier");
  wait_politely(r, [] { return false; });
}

/// Every rank's `mine`, by rank, on every rank (collective).
inline std::vector<std::string> all_gather_bytes(MPI_Comm comm, const std::string& mine) {
  int size = 0;
  check(MPI_Comm_size(comm, &size), "MPI_Comm_size");
  const auto n = static_cast<std::size_t>(size);
  if (mine.size() > static_cast<std::size_t>(INT32_MAX))
    throw limit_error("pdd::mpi: a rank's report exceeds 2 GiB");
  const int len = static_cast<int>(mine.size());
  std::vector<int> lens(n), offsets(n);
  check(MPI_Allgather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, comm), "MPI_Allgather");
  long long total = 0;
  for (std::size_t r = 0; r < n; ++r) {
    if (total > INT32_MAX) throw limit_error("pdd::mpi: the ranks' reports exceed 2 GiB");
    offsets[r] = static_cast<int>(total);
    total += lens[r];
  }
  std::string all(static_cast<std::size_t>(total), '\0');
  check(MPI_Allgatherv(mine.data(), len, MPI_CHAR, all.data(), lens.data(), offsets.data(),
                       MPI_CHAR, comm),
        "MPI_Allgatherv");
  std::vector<std::string> out(n);
  for (std::size_t r = 0; r < n; ++r)
    out[r] = all.substr(static_cast<std::size_t>(offsets[r]), static_cast<std::size_t>(lens[r]));
  return out;
}

/// What kind of exception crossed ranks: the pdd error classes the drivers tell apart
/// (exit codes, messages), any other std::exception, and none.
enum class error_kind : std::int32_t {
  none,
  error,
  geometry,
  decomposition,
  decoupling,
  meshing,
  unresolvable, ///< pdd::unresolvable_input_error (a meshing_error with its own exit code)
  limit,
  sizing,
  internal,
  foreign
};

/// An exception as plain data: its kind, its subdomain (meshing errors) and its message.
struct wire_error {
  error_kind kind = error_kind::none;
  long long subdomain = -1;
  std::string message;
};

/// The kind, subdomain and message of `e` (kind none for a null pointer).
inline wire_error encode(const std::exception_ptr& e) {
  if (!e) return {};
  try {
    std::rethrow_exception(e);
  } catch (const unresolvable_input_error& m) {
    return {error_kind::unresolvable, m.subdomain(), m.what()};
  } catch (const meshing_error& m) {
    return {error_kind::meshing, m.subdomain(), m.what()};
  } catch (const geometry_error& g) {
    return {error_kind::geometry, -1, g.what()};
  } catch (const decomposition_error& d) {
    return {error_kind::decomposition, -1, d.what()};
  } catch (const decoupling_error& d) {
    return {error_kind::decoupling, -1, d.what()};
  } catch (const limit_error& l) {
    return {error_kind::limit, -1, l.what()};
  } catch (const sizing_error& s) {
    return {error_kind::sizing, -1, s.what()};
  } catch (const internal_error& i) {
    return {error_kind::internal, -1, i.what()};
  } catch (const error& x) {
    return {error_kind::error, -1, x.what()};
  } catch (const std::exception& x) {
    return {error_kind::foreign, -1, x.what()};
  } catch (...) {
    return {error_kind::foreign, -1, "an exception that is not a std::exception"};
  }
}

inline void put(byte_writer& w, const wire_error& e) {
  w.put(e.kind);
  w.put(e.subdomain);
  w.put_string(e.message);
}

inline wire_error get_error(byte_reader& r) {
  wire_error e;
  e.kind = r.get<error_kind>();
  e.subdomain = r.get<long long>();
  e.message = r.get_string();
  return e;
}

/// Throws an exception of e's class with e's message (what() reads the same as the original's;
/// ids other than a meshing error's subdomain are not carried).
[[noreturn]] inline void rethrow(const wire_error& e) {
  switch (e.kind) {
  case error_kind::meshing:
  case error_kind::unresolvable: {
    const std::string prefix = "subdomain " + std::to_string(e.subdomain) + ": ";
    const bool prefixed = e.subdomain >= 0 && e.message.rfind(prefix, 0) == 0;
    const std::string message = prefixed ? e.message.substr(prefix.size()) : e.message;
    if (e.kind == error_kind::unresolvable) throw unresolvable_input_error(e.subdomain, message);
    throw meshing_error(e.subdomain, message);
  }
  case error_kind::geometry:
    throw geometry_error(e.message);
  case error_kind::decomposition:
    throw decomposition_error(e.message);
  case error_kind::decoupling:
    throw decoupling_error(e.message);
  case error_kind::limit:
    throw limit_error(e.message);
  case error_kind::sizing:
    throw sizing_error(e.message);
  case error_kind::internal:
    throw internal_error(e.message);
  case error_kind::error:
    throw error(e.message);
  case error_kind::foreign:
  case error_kind::none:
    break;
  }
  throw std::runtime_error(e.message);
}

} // namespace pdd::mpi::detail
