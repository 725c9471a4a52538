/// \file resume_options.hpp
/// --resume and --overwrite of a per-subdomain output (issue 40): the run's fingerprint from
/// the shared options (mesh_options.hpp), the manifest's JSON (pdd::piece_manifest; no pdd
/// header uses JSON) and the output directory's preparation: refused when it is not empty,
/// cleared with --overwrite, and with --resume checked against the manifest, whose intact
/// pieces are kept. For pdd-mesh now, and for pdd-mesh-mpi.
#pragma once

#include "mesh_options.hpp"

#include <pdd/core/index.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/piece_files.hpp>
#include <pdd/io/piece_manifest.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <charconv>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace pdd::drivers {

/// The values of --resume and --overwrite.
struct resume_options {
  bool resume = false, overwrite = false;
};

/// Registers --resume and --overwrite on `app`; both need --output-per-subdomain (`per`).
inline void add_resume_options(CLI::App& app, resume_options& r, CLI::Option* per) {
  auto* resume = app.add_flag("--resume", r.resume,
                              "continue a killed or failed --output-per-subdomain run: keep the "
                              "pieces its manifest lists intact, mesh the others (refused when "
                              "the input, an option, the version or the plan differs)")
                     ->needs(per);
  app.add_flag("--overwrite", r.overwrite,
               "replace the pieces, index and manifest of an existing non-empty "
               "--output-per-subdomain directory (refused without it or --resume)")
      ->needs(per)
      ->excludes(resume);
}

/// A double as its shortest round-trip text ("0.001", "inf").
inline std::string fingerprint_number(double x) {
  char text[64];
  const auto r = std::to_chars(text, text + sizeof text, x);
  return std::string(text, r.ptr);
}

/// The fingerprint of a run with options `o` whose plan has `n` subdomains on `path`: the
/// input's and the sizing files' checksums, every option that changes the mesh or its files,
/// pdd's `version`. (--threads, --max-triangles, the disk check and --stats do not.)
/// \throws pdd::error when a file cannot be read.
inline pdd::run_fingerprint mesh_fingerprint(const mesh_options& o, std::size_t n,
                                             const std::string& path, std::string_view version) {
  pdd::run_fingerprint f;
  const auto file = [](const std::string& p) {
    return p.empty() ? std::string("none") : p + " (" + pdd::file_fingerprint(p) + ")";
  };
  f["input"] = pdd::file_fingerprint(o.input);
  f["--min-angle"] = fingerprint_number(o.min_angle);
  f["--max-area"] = fingerprint_number(o.max_area);
  f["--sizing"] = o.sizing.expression.empty() ? "none" : o.sizing.expression;
  f["--background"] = file(o.sizing.background_mesh);
  f["--area-grid"] = file(o.sizing.area_grid);
  f["--subdomains"] = o.subdomains == 0 ? "auto" : std::to_string(o.subdomains);
  f["--r1"] = fingerprint_number(o.gradation.r1);
  f["--r2"] = fingerprint_number(o.gradation.r2);
  f["--geometric-sizing"] = o.geometric_sizing;
  f["--geometric-max-subdomains"] = std::to_string(o.geometric_max_subdomains);
  f["--geometric-field"] = o.geometric_field;
  f["--kernel"] = o.kernel;
  f["--format"] = pdd::to_string(o.format);
  f["pdd version"] = std::string(version);
  f["plan subdomains"] = std::to_string(n);
  f["plan path"] = path;
  return f;
}

/// The manifest as JSON: {"checksum": "crc64-xz", "fingerprint": {...}, "pieces": [{"id",
/// "file", "size", "checksum" (16 hex digits), "triangles", "vertices"}, ...]} in id order.
inline nlohmann::json manifest_json(const pdd::piece_manifest& m) {
  nlohmann::json pieces = nlohmann::json::array();
  for (const auto& [id, p] : m.pieces) {
    char crc[24];
    std::snprintf(crc, sizeof crc, "%016llx", static_cast<unsigned long long>(p.checksum));
    pieces.push_back({{"id", id},
                      {"file", p.file},
                      {"size", p.size},
                      {"checksum", crc},
                      {"triangles", p.triangles},
                      {"vertices", p.vertices}});
  }
  return {{"checksum", pdd::piece_checksum_name},
          {"fingerprint", m.fingerprint},
          {"pieces", std::move(pieces)}};
}

/// Writes the manifest `<dir>/pdd-manifest.json` atomically and durably.
inline void save_manifest(const std::filesystem::path& dir, const pdd::piece_manifest& m) {
  pdd::write_file_atomically(dir / pdd::piece_manifest_name,
                             [&](std::ostream& os) { os << manifest_json(m).dump(1) << '\n'; });
}

/// The manifest in `dir`, or nothing when there is none.
/// \throws pdd::error naming the file when it is not a manifest pdd wrote.
inline std::optional<pdd::piece_manifest> read_manifest(const std::filesystem::path& dir) {
  const std::filesystem::path p = dir / pdd::piece_manifest_name;
  std::ifstream in(p);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    if (j.at("checksum").get<std::string>() != pdd::piece_checksum_name)
      throw pdd::error("unknown checksum " + j.at("checksum").dump());
    pdd::piece_manifest m;
    m.fingerprint = j.at("fingerprint").get<pdd::run_fingerprint>();
    for (const nlohmann::json& e : j.at("pieces")) {
      pdd::piece_record& r = m.pieces[e.at("id").get<pdd::index_t>()];
      r.file = e.at("file").get<std::string>();
      r.size = e.at("size").get<std::uintmax_t>();
      r.checksum = std::stoull(e.at("checksum").get<std::string>(), nullptr, 16);
      r.triangles = e.at("triangles").get<std::size_t>();
      r.vertices = e.at("vertices").get<std::size_t>();
    }
    return m;
  } catch (const std::exception& e) {
    throw pdd::error(p.string() + ": not a pdd manifest (" + e.what() +
                     "); use --overwrite to start again");
  }
}

/// The bytes of the pieces the manifest in `dir` lists that are there with their size (what a
/// --resume may keep; their checksums are checked later), for the disk-space check. 0 without
/// a manifest. \throws as read_manifest.
inline std::uintmax_t resumable_bytes(const std::filesystem::path& dir) {
  const std::optional<pdd::piece_manifest> m = read_manifest(dir);
  std::uintmax_t n = 0;
  for (const auto& [id, record] : m ? m->pieces : std::map<pdd::index_t, pdd::piece_record>{}) {
    std::error_code ec;
    if (std::filesystem::file_size(dir / record.file, ec) == record.size && !ec) n += record.size;
  }
  return n;
}

/// True when `dir` exists and holds any entry.
inline bool non_empty_directory(const std::filesystem::path& dir) {
  std::error_code ec;
  return std::filesystem::is_directory(dir, ec) &&
         std::filesystem::directory_iterator(dir, ec) != std::filesystem::directory_iterator();
}

/// The manifest a --resume run starts from: the fingerprint checked against `now`, the intact
/// pieces kept, everything else of pdd's in `dir` removed (the index, temporaries, pieces not
/// kept), and the manifest saved with the kept pieces only.
/// \throws pdd::error naming what differs when the fingerprint does.
inline pdd::piece_manifest resumed_manifest(const std::filesystem::path& dir, pdd::piece_format f,
                                            const pdd::run_fingerprint& now) {
  pdd::piece_manifest m{now, {}};
  if (const std::optional<pdd::piece_manifest> then = read_manifest(dir)) {
    const std::vector<std::string> diff = pdd::fingerprint_differences(then->fingerprint, now);
    if (!diff.empty()) {
      std::string text = "cannot resume '" + dir.string() + "': ";
      for (std::size_t i = 0; i < diff.size(); ++i)
        text += (i ? "; " : "") + diff[i];
      throw pdd::error(text + " (use --overwrite to start again)");
    }
    m.pieces = pdd::intact_pieces(*then, dir, std::stoull(now.at("plan subdomains")), f);
  }
  std::vector<std::string> keep{pdd::piece_manifest_name};
  for (const auto& [id, record] : m.pieces)
    keep.push_back(record.file);
  pdd::remove_piece_outputs(dir, keep);
  save_manifest(dir, m);
  return m;
}

/// Prepares `dir` for a run with fingerprint `now` and returns the manifest it starts from:
/// with --resume resumed_manifest; with --overwrite pdd's files removed (others stay);
/// otherwise a non-empty directory is refused.
/// \throws pdd::error (exit code 1) with what to do when it is refused.
inline pdd::piece_manifest prepare_output_directory(const std::filesystem::path& dir,
                                                    pdd::piece_format f, const resume_options& r,
                                                    const pdd::run_fingerprint& now) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw pdd::error("cannot create directory '" + dir.string() + "': " + ec.message());
  if (r.resume) return resumed_manifest(dir, f, now);
  if (r.overwrite)
    pdd::remove_piece_outputs(dir);
  else if (non_empty_directory(dir))
    throw pdd::error("the output directory '" + dir.string() +
                     "' is not empty: --resume continues the run that wrote it, --overwrite "
                     "replaces its pieces (or choose an empty directory)");
  pdd::piece_manifest m{now, {}};
  save_manifest(dir, m);
  return m;
}

} // namespace pdd::drivers
