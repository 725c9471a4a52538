/// \file file_names.hpp
/// pdd::triangle::file_names: the files a `triangle` command line reads and writes, by
/// Triangle 1.6's rules (its README and `triangle -h`): `key.poly` -> `key.1.node`,
/// `key.1.ele`, `key.1.poly`; `key.1.poly` -> `key.2.*`; -I drops the iteration number; without
/// p the input is `key.node` (a vertex set).
#pragma once

#include <pdd/triangle/switches.hpp>

#include <cstddef>
#include <string>
#include <string_view>

namespace pdd::triangle {

/// Input and output names of one run (empty: not read / not written).
struct file_names {
  std::string base;            ///< the input name without its extension (`dir/key`, `dir/key.1`)
  std::string poly;            ///< the .poly read (-p)
  std::string in_node;         ///< the .node read (without -p; with -r)
  /// \var in_ele
  /// -r: the previous mesh's .ele read (`<base>.ele`).
  /// \var in_area
  /// -r with a bare -a: the previous mesh's .area read (`<base>.area`).
  std::string in_ele, in_area;
  /// \var node
  /// The output .node (`<stem>.node`); empty with -N, and with -I when the .node was read.
  /// \var ele
  /// The output .ele (`<stem>.ele`); empty with -E.
  /// \var out_poly
  /// The output .poly (`<stem>.poly`), with -p or -c only; empty with -P or -I.
  /// \var neigh
  /// The output .neigh (`<stem>.neigh`), with -n only.
  std::string node, ele, out_poly, neigh;
  /// \var edge
  /// The output .edge (`<stem>.edge`), with -e only.
  /// \var v_node
  /// The Voronoi diagram's .v.node (`<stem>.v.node`), with -v only.
  /// \var v_edge
  /// The Voronoi diagram's .v.edge (`<stem>.v.edge`), with -v only.
  std::string edge, v_node, v_edge;
};

namespace detail {
/// Removes `ext` from the end of name; true if it was there.
inline bool strip_suffix(std::string& name, std::string_view ext) {
  if (name.size() <= ext.size() || !std::string_view(name).ends_with(ext)) return false;
  name.resize(name.size() - ext.size());
  return true;
}
} // namespace detail

/// The names Triangle uses for input `name` and switches `sw`, which this updates as Triangle
/// does: a `.poly` name sets p, `.node` is dropped from the name. Output stem: `<base>.1`
/// when the base has no numeric last component, `<stem>.<n+1>` when it ends in `.<n>`
/// (`key.1.poly` writes `key.2.*`, as Triangle numbers iterations), `<base>` with -I. Outputs that
/// -N, -E, -P suppress are left empty; with -I, the .poly is never written and neither is the .node
/// when `node_was_read` (Triangle will not overwrite its input); the .poly only with -p or -c;
/// .neigh only with -n, .edge with -e, .v.node and .v.edge with -v. With -r the previous mesh is
/// `<base>.node` and `<base>.ele` (with -p its `<base>.poly`, with a bare -a its `<base>.area`,
/// read if it exists). \throws switch_error for an `.area` or `.ele` name without -r.
inline file_names make_file_names(std::string name, switches& sw, bool node_was_read = false) {
  for (const char* ext : {".area", ".ele"})
    if (detail::strip_suffix(name, ext) && !sw.refine)
      throw switch_error("'" + name + ext + "': an " + (ext + 1) +
                         " file is read only to refine a previous mesh (-r)");
  detail::strip_suffix(name, ".node");
  if (detail::strip_suffix(name, ".poly")) sw.poly = true;
  file_names f;
  f.base = name;
  if (sw.refine) {
    f.in_node = name + ".node";
    f.in_ele = name + ".ele";
    if (sw.poly) f.poly = name + ".poly";
    if (sw.regional_areas) f.in_area = name + ".area";
  } else if (sw.poly) {
    f.poly = name + ".poly";
  } else {
    f.in_node = name + ".node";
  }
  std::string stem = name + ".1";
  const std::size_t dot = name.find_last_of('.');
  if (dot != std::string::npos && dot > 0 && dot + 1 < name.size() &&
      name.find_first_not_of("0123456789", dot + 1) == std::string::npos &&
      name.size() - dot - 1 <= 9 && name.find('/', dot) == std::string::npos)
    stem = name.substr(0, dot + 1) + std::to_string(std::stoull(name.substr(dot + 1)) + 1);
  if (sw.no_iteration_numbers) stem = name;
  if (!sw.no_node && !(sw.no_iteration_numbers && node_was_read)) f.node = stem + ".node";
  if (!sw.no_ele) f.ele = stem + ".ele";
  if ((sw.poly || sw.convex) && !sw.no_poly && !sw.no_iteration_numbers)
    f.out_poly = stem + ".poly";
  if (sw.neighbors) f.neigh = stem + ".neigh";
  if (sw.edges) f.edge = stem + ".edge";
  if (sw.voronoi) {
    f.v_node = stem + ".v.node";
    f.v_edge = stem + ".v.edge";
  }
  return f;
}

} // namespace pdd::triangle
