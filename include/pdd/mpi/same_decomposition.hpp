/// \file same_decomposition.hpp
/// pdd::mpi::fingerprint and pdd::mpi::check_same_decomposition: proof that every rank built
/// the same decoupled decomposition (pdd::mpi::mesh_subdomains' precondition) before meshing.
#pragma once

#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/errors.hpp>
#include <pdd/mpi/detail/wire.hpp>

#include <mpi.h>

#include <cstdint>
#include <cstring>
#include <string>

namespace pdd::mpi {

namespace detail {
/// FNV-1a over the bytes of trivially copyable values.
struct fnv1a {
  std::uint64_t h = 14695981039346656037ull;
  template <class T>
  void add(const T& v) {
    unsigned char b[sizeof v];
    std::memcpy(b, &v, sizeof v);
    for (const unsigned char c : b)
      h = (h ^ c) * 1099511628211ull;
  }
};
} // namespace detail

/// A 64-bit FNV-1a hash of what the kernel inputs are built from: the decomposition's vertex
/// coordinates (bits), every subdomain's loops and inner constraints, the path edges (endpoints,
/// sides, k, pieces), the split points and the corners of the shield triangles. Equal
/// decompositions hash equal; a difference in any of these (another binary, another input, a
/// non-deterministic build) almost surely not. Complexity linear in the decomposition.
inline std::uint64_t fingerprint(const decoupled_decomposition& dd) {
  detail::fnv1a f;
  f.add(dd.parts.vertices.size());
  for (const point& p : dd.parts.vertices) {
    f.add(p.x);
    f.add(p.y);
  }
  for (const subdomain& s : dd.parts.subdomains) {
    for (const auto& loop : s.loops) {
      f.add(loop.size());
      for (const index_t v : loop)
        f.add(v);
    }
    f.add(s.inner.size());
    for (const inner_constraint& c : s.inner) {
      f.add(c.a);
      f.add(c.b);
      f.add(c.segment);
    }
  }
  f.add(dd.k);
  for (const path_edge& e : dd.path) {
    f.add(e.u);
    f.add(e.v);
    f.add(e.sides);
    f.add(e.k);
    f.add(e.pieces);
  }
  for (const point& p : dd.points) {
    f.add(p.x);
    f.add(p.y);
  }
  for (const auto& shields : dd.shields) {
    f.add(shields.size());
    for (const shield_triangle& t : shields)
      for (const point& p : {t.apex, t.b, t.c}) {
        f.add(p.x);
        f.add(p.y);
      }
  }
  return f.h;
}

/// Compares every rank's fingerprint(dd) with rank 0's. Collective.
/// \throws pdd::internal_error on a rank whose decomposition differs from rank 0's (wrap the
/// call in pdd::mpi::collectively so that every rank fails with it).
inline void check_same_decomposition(MPI_Comm comm, const decoupled_decomposition& dd) {
  const std::uint64_t mine = fingerprint(dd);
  std::uint64_t root = mine;
  detail::check(MPI_Bcast(&root, 1, MPI_UINT64_T, 0, comm), "MPI_Bcast");
  if (mine == root) return;
  int rank = 0;
  detail::check(MPI_Comm_rank(comm, &rank), "MPI_Comm_rank");
  throw internal_error("rank " + std::to_string(rank) +
                       " built another decoupled decomposition than rank 0 (fingerprint " +
                       std::to_string(mine) + " != " + std::to_string(root) +
                       "): every rank must run the same program on the same input");
}

} // namespace pdd::mpi
