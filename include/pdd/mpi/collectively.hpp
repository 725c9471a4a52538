/// \file collectively.hpp
/// pdd::mpi::collectively: runs a step on every rank of a communicator and makes its failure
/// on any rank the failure of every rank, so that all ranks leave a failed step together (no
/// rank left waiting in a later collective call) with the same exception.
#pragma once

#include <pdd/mpi/detail/wire.hpp>

#include <mpi.h>

#include <exception>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace pdd::mpi {

/// The agreement step of pdd::mpi::collectively: `failure` is this rank's exception (null: none).
/// When any rank has one, every rank throws the lowest failing rank's. Collective.
inline void rethrow_first_failure(MPI_Comm comm, const std::exception_ptr& failure) {
  detail::polite_barrier(comm);
  detail::byte_writer w;
  detail::put(w, detail::encode(failure));
  const std::vector<std::string> all = detail::all_gather_bytes(comm, w.bytes);
  int rank = 0;
  detail::check(MPI_Comm_rank(comm, &rank), "MPI_Comm_rank");
  for (std::size_t r = 0; r < all.size(); ++r) {
    detail::byte_reader in(all[r]);
    const detail::wire_error e = detail::get_error(in);
    if (e.kind == detail::error_kind::none) continue;
    if (static_cast<int>(r) == rank) std::rethrow_exception(failure);
    detail::rethrow(e);
  }
}

/// Runs body() on every rank of `comm` (collective: every rank calls it) and agrees on the
/// outcome: when body() threw on any rank, every rank throws the exception of the lowest
/// failing rank, that rank its original exception and the others one of the same pdd error
/// class with the same what() (see pdd::mpi::detail::rethrow). Waiting ranks sleep rather than
/// spin (pdd::mpi::detail::polite_barrier).
/// \returns body()'s result on every rank (each rank its own).
/// Complexity: body() plus one barrier and one all-gather of the error messages.
template <class Body>
auto collectively(MPI_Comm comm, Body&& body) -> decltype(body()) {
  using result = decltype(body());
  std::exception_ptr failure;
  auto run = [&] {
    try {
      if constexpr (std::is_void_v<result>) {
        body();
        return;
      } else {
        return body();
      }
    } catch (...) {
      failure = std::current_exception();
      if constexpr (!std::is_void_v<result>) return result{};
    }
  };
  if constexpr (std::is_void_v<result>) {
    run();
    rethrow_first_failure(comm, failure);
  } else {
    result r = run();
    rethrow_first_failure(comm, failure);
    return r;
  }
}

} // namespace pdd::mpi
