// pdd_mpi_throwing_mesher INPUT.poly MAX_AREA N DIR FAIL_ID [unresolvable]: an MPI program over
// the library API (not a driver): every rank builds the decoupled decomposition of INPUT.poly
// with N subdomains, and pdd::mpi::mesh_subdomains meshes it into DIR
// (pdd::mpi::vtu_directory_sink) with a kernel that throws on subdomain FAIL_ID (-1: never): a
// std::runtime_error, or with `unresolvable` a pdd::unresolvable_input_error (whose class must
// cross the ranks). Rank 0 prints the error, or the statistics; every rank checks that all ranks
// report the same statistics. Exit code: 0; 4 for a meshing error; 5 for an
// unresolvable_input_error; 1 when the statistics disagree or are inconsistent. Run by
// tests/mpi/mpi_test.cpp under mpiexec.
#include <pdd/io/poly.hpp>
#include <pdd/kernels/default_mesher.hpp>
#include <pdd/mpi/collectively.hpp>
#include <pdd/mpi/mesh_subdomains.hpp>
#include <pdd/mpi/vtu_directory_sink.hpp>
#include <pdd/pipeline.hpp>

#include <mpi.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

/// The CGAL kernel, except on the one subdomain whose input vertices are `trigger`.
struct throwing_mesher {
  std::vector<pdd::point> trigger;
  bool unresolvable = false; ///< throw pdd::unresolvable_input_error, not std::runtime_error
  template <pdd::SizingField S>
  pdd::mesher_result mesh(const pdd::pslg& d, const pdd::mesh_criteria& c, const S& s) const {
    if (!trigger.empty() && d.vertices == trigger) {
      if (unresolvable) throw pdd::unresolvable_input_error(-1, "injected input limit");
      throw std::runtime_error("injected failure");
    }
    return pdd::default_mesher{}.mesh(d, c, s);
  }
};
static_assert(pdd::DelaunayMesher<throwing_mesher>);

/// Rank 0's statistics must be every rank's; each subdomain delivered once, by some rank.
bool consistent(const pdd::mpi::distributed_meshing_statistics& st, int rank) {
  std::size_t by_subdomain = 0, by_rank = 0;
  for (const auto& s : st.meshing.subdomains)
    by_subdomain += s.triangles;
  for (const auto& r : st.ranks)
    by_rank += r.triangles;
  bool ok = by_subdomain == by_rank && by_subdomain > 0;
  for (const int r : st.subdomain_rank)
    ok = ok && r >= 0 && r < static_cast<int>(st.ranks.size());
  unsigned long long total = by_subdomain, root = total;
  MPI_Bcast(&root, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  ok = ok && root == total;
  if (rank == 0)
    std::printf("meshed %zu subdomains, %zu triangles, imbalance %.3f\n",
                st.meshing.subdomains.size(), by_subdomain, st.imbalance());
  return ok;
}

int run(char** argv, int rank) {
  pdd::generate_options o;
  o.criteria.max_area = std::stod(argv[2]);
  o.subdomains = std::stoul(argv[3]);
  o.threads = 2;
  pdd::pipeline<> path(pdd::read_poly(argv[1]), o);
  path.decouple();
  pdd::decoupled_decomposition& dd = path.decoupled();
  const long long fail = std::stoll(argv[5]);
  throwing_mesher mesher;
  mesher.unresolvable = argv[6] != nullptr && std::string(argv[6]) == "unresolvable";
  if (fail >= 0) mesher.trigger = dd.input(static_cast<pdd::index_t>(fail)).domain.vertices;
  pdd::mpi::vtu_directory_sink files(MPI_COMM_WORLD, argv[4]);
  try {
    const auto st = pdd::mpi::mesh_subdomains(
        MPI_COMM_WORLD, dd, {o.criteria, o.decoupling.max_repairs, o.sizing}, mesher, 2, files);
    return consistent(st, rank) ? 0 : 1;
  } catch (const pdd::meshing_error&) {
    files.remove_written();
    throw;
  }
}

} // namespace

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  int rc = 2;
  if (argc == 6 || argc == 7) {
    try {
      rc = run(argv, rank);
    } catch (const pdd::meshing_error& e) {
      if (rank == 0) std::fprintf(stderr, "error: %s\n", e.what());
      rc = dynamic_cast<const pdd::unresolvable_input_error*>(&e) ? 5 : 4;
    }
  } else if (rank == 0) {
    std::fprintf(stderr, "usage: %s INPUT.poly MAX_AREA N DIR FAIL_ID [unresolvable]\n", argv[0]);
  }
  MPI_Finalize();
  return rc;
}
