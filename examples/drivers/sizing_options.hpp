/// \file sizing_options.hpp
/// The sizing fields of a pdd-mesh run from its options (--sizing, --background, --area-grid)
/// and the .poly's regional area bounds.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/io/area_grid.hpp>
#include <pdd/io/background_mesh.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/expression.hpp>
#include <pdd/sizing/min_sizing.hpp>
#include <pdd/sizing/regional.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace pdd::drivers {

/// Where the sizing fields come from (an empty string: not given).
struct sizing_sources {
  std::string expression;      ///< --sizing: muParser expression of x and y
  std::string background_mesh; ///< --background FILE.node
  std::string area_grid;       ///< --area-grid FILE
};

/// The names of the fields (and "uniform" for a finite --max-area) for --stats: "none", one
/// name, or "min(a, b, ...)".
inline std::string sizing_kind(const std::vector<pdd::any_sizing>& fields, double max_area) {
  std::vector<std::string> names;
  for (const auto& f : fields)
    names.push_back(f.kind());
  if (std::isfinite(max_area)) names.emplace_back("uniform");
  if (names.empty()) return "none";
  if (names.size() == 1) return names[0];
  std::string kind = "min(";
  for (std::size_t i = 0; i < names.size(); ++i)
    kind += names[i] + (i + 1 < names.size() ? ", " : ")");
  return kind;
}

/// The sizing field of a run: the minimum of --sizing, --background, --area-grid and the
/// .poly's regional areas (each when given); empty when none is. `kind` names it, with
/// "uniform" for a finite max_area, for --stats. \throws pdd::sizing_error, pdd::input_error
/// (file:line) or pdd::geometry_error (a region point) on bad input.
inline pdd::any_sizing sizing_field(const sizing_sources& o, const pdd::pslg& domain,
                                    double max_area, std::string& kind) {
  std::vector<pdd::any_sizing> fields;
  if (!o.expression.empty()) fields.emplace_back(pdd::expression_sizing(o.expression));
  if (!o.background_mesh.empty()) fields.emplace_back(pdd::read_background_mesh(o.background_mesh));
  if (!o.area_grid.empty()) fields.emplace_back(pdd::read_area_grid(o.area_grid));
  for (const pdd::region& reg : domain.regions)
    if (reg.max_area > 0.0) {
      fields.emplace_back(pdd::regional_sizing(domain));
      break;
    }
  kind = sizing_kind(fields, max_area);
  if (fields.empty()) return {};
  pdd::any_sizing combined = fields[0];
  for (std::size_t i = 1; i < fields.size(); ++i)
    combined = pdd::min_sizing(combined, fields[i]);
  return combined;
}

} // namespace pdd::drivers
