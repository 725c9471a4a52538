// Consumer of an installed pdd: reads a .poly, meshes it with the default kernel, verifies.
#include <pdd/pdd.hpp>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s INPUT.poly\n", argv[0]);
    return 2;
  }
  const pdd::pslg domain = pdd::read_poly(argv[1]);
  pdd::generate_options options;
  options.criteria.max_area = 1e-3;
  options.subdomains = 4;
  const pdd::generate_result r = pdd::generate(domain, options);
  const pdd::verification_report report =
      pdd::verify(r.mesh, domain, pdd::verify_options{.criteria = options.criteria});
  std::printf("pdd_consumer: %zu triangles in %zu subdomains, verified: %s\n",
              r.mesh.triangles.size(), r.statistics.subdomains, report.ok() ? "yes" : "NO");
  return report.ok() ? 0 : 1;
}
