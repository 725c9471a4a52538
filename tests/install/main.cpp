// Consumer of an installed pdd: reads a .poly, meshes it with the default kernel, verifies;
// then meshes it again graded by a muParser expression (pdd::expression target) and verifies
// the mesh against that field. It prints the installed pdd/version.hpp's version. It includes
// the headers it uses (pdd/pdd.hpp would include every public header).
#include <pdd/generate.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/sizing/expression.hpp>
#include <pdd/version.hpp>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s INPUT.poly\n", argv[0]);
    return 2;
  }
  std::printf("pdd_consumer: pdd %s (installed pdd/version.hpp)\n", PDD_VERSION_STRING);
  const pdd::pslg domain = pdd::read_poly(argv[1]);
  pdd::generate_options options;
  options.criteria.max_area = 1e-3;
  options.subdomains = 4;
  const pdd::generate_result r = pdd::generate(domain, options);
  const pdd::verify_options vo{.criteria = options.criteria};
  const pdd::verification_report report = pdd::verify(r.mesh, domain, vo);
  std::printf("pdd_consumer: %zu triangles in %zu subdomains, verified: %s\n",
              r.mesh.triangles.size(), r.statistics.subdomains, report.ok() ? "yes" : "NO");

  const pdd::expression_sizing field("1e-4 + 1e-3 * x^2");
  options.sizing = field;
  const pdd::generate_result g = pdd::generate(domain, options);
  const pdd::verification_report graded = pdd::verify(g.mesh, domain, vo, field);
  std::printf("pdd_consumer: graded by %s: %zu triangles, verified: %s\n", field.text().c_str(),
              g.mesh.triangles.size(), graded.ok() ? "yes" : "NO");
  return report.ok() && graded.ok() ? 0 : 1;
}
