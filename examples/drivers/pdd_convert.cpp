// pdd-convert: turns pdd's binary per-subdomain output (pdd-mesh --format binary) into VTU, for
// ParaView, VisIt or meshio.
//
//   pdd-convert DIR/mesh.pddi OUTDIR [--quiet]    every piece -> OUTDIR/subdomain_<id>.vtu, and
//                                                 OUTDIR/mesh.pvtu over them (written last)
//   pdd-convert PIECE.pddm OUT.vtu [--quiet]      one piece -> one .vtu
//
// The .vtu files are byte for byte those `pdd-mesh --format vtu` writes for the same mesh. Every
// file is read with its checks (docs/binary-mesh-format.md: magic, version, size, checksum,
// indices) and written atomically; a failed conversion of an index leaves no .pvtu and removes
// the .vtu pieces it wrote.
//
// Exit codes: 0 converted, 1 a file cannot be read or written or is not pdd's binary format
// (truncated, tampered, wrong version; the message names the file and the reason), 2 usage,
// 4 internal error.
#include "exit_code.hpp"
#include "version_flag.hpp"

#include <pdd/errors.hpp>
#include <pdd/io/binary_mesh.hpp>
#include <pdd/io/piece_files.hpp>
#include <pdd/io/vtu.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace pdd::drivers; // exit codes

struct cli_options {
  std::string input, output;
  bool quiet = false;
};

/// True when `path` starts as a .pddi index does ("pdd-mesh-index").
bool is_binary_index(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string start(std::char_traits<char>::length(pdd::binary_mesh_index_tag), '\0');
  in.read(start.data(), static_cast<std::streamsize>(start.size()));
  return in && start == pdd::binary_mesh_index_tag;
}

/// Converts every piece of the index into `out` and writes out/mesh.pvtu last; removes the
/// pieces written so far when one fails. Returns the number of pieces.
std::size_t convert_index(const fs::path& index, const fs::path& out) {
  const std::vector<fs::path> pieces = pdd::read_binary_mesh_index(index);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw pdd::error("cannot create directory '" + out.string() + "': " + ec.message());
  std::vector<std::string> names;
  try {
    for (const fs::path& piece : pieces) {
      const std::string name = fs::path(piece.filename()).replace_extension(".vtu").string();
      pdd::write_vtu(out / name, pdd::read_binary_mesh(piece));
      names.push_back(name);
    }
    pdd::write_pvtu(out / "mesh.pvtu", names);
  } catch (const pdd::error&) {
    for (const std::string& name : names) {
      std::error_code ignored; // best effort: the conversion has failed already
      fs::remove(out / name, ignored);
    }
    throw;
  }
  return pieces.size();
}

int run(const cli_options& o) {
  const fs::path input = o.input;
  if (pdd::detect_piece_format(input) != pdd::piece_format::binary)
    throw pdd::error(input.string() + ": already VTU (pdd-convert reads pdd's binary format)");
  if (is_binary_index(input)) {
    const std::size_t n = convert_index(input, o.output);
    if (!o.quiet)
      std::printf("pdd-convert: wrote %s/mesh.pvtu and %zu .vtu pieces\n", o.output.c_str(), n);
  } else {
    pdd::write_vtu(o.output, pdd::read_binary_mesh(input));
    if (!o.quiet) std::printf("pdd-convert: wrote %s\n", o.output.c_str());
  }
  return ok;
}

} // namespace

int main(int argc, char** argv) {
  cli_options o;
  CLI::App app{"pdd-convert: pdd's binary per-subdomain mesh (.pddi/.pddm) to VTU (.pvtu/.vtu)"};
  pdd::drivers::add_version_flag(app, "pdd-convert");
  app.add_option("input", o.input, "a .pddi index (pdd-mesh --format binary) or one .pddm piece")
      ->required();
  app.add_option("output", o.output, "for an index: the output folder; for a piece: the .vtu file")
      ->required();
  app.add_flag("-q,--quiet", o.quiet, "print nothing but errors");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? ok : usage;
  }
  return pdd::drivers::run_reporting_errors("pdd-convert", o.input, [&] { return run(o); });
}
