// pdd-geometry: writes pdd's generated model domains as Triangle .poly files.
//
//   pdd-geometry key|pipe -o FILE.poly [--svg FILE.svg]
//
// The key (54 segments, one hole) and the pipe cross-section (a circle of 576 segments with 9
// circular holes) are the dissertation's model domains; examples/data holds their output.
#include "exit_code.hpp"
#include "version_flag.hpp"

#include <pdd/errors.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/io/svg.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  std::string name, output, svg;
  std::size_t outer = 576, hole = 64;
  CLI::App app{"pdd-geometry: write a generated model domain as a Triangle .poly file"};
  pdd::drivers::add_version_flag(app, "pdd-geometry");
  app.add_option("domain", name, "key or pipe")->required()->check(CLI::IsMember({"key", "pipe"}));
  app.add_option("-o,--output", output, "output .poly file")->required();
  app.add_option("--svg", svg, "also draw the domain to this SVG file");
  app.add_option("--outer-segments", outer, "pipe: segments of the outer circle")
      ->check(CLI::Range(6, 1 << 24));
  app.add_option("--hole-segments", hole, "pipe: segments of each hole")
      ->check(CLI::Range(6, 1 << 24));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return pdd::drivers::run_reporting_errors("pdd-geometry", output, [&] {
    const pdd::pslg g = name == "key" ? pdd::key_domain() : pdd::pipe_domain(outer, hole);
    pdd::validate(g);
    pdd::write_poly(output, g);
    if (!svg.empty()) pdd::write_svg(svg, g);
    std::printf("pdd-geometry: wrote %s (%zu vertices, %zu segments, %zu holes)\n", output.c_str(),
                g.vertices.size(), g.segments.size(), g.holes.size());
    return 0;
  });
}
