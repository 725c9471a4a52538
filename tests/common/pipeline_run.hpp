// A pipeline run for the tests: the merged mesh (the whole domain when the plan is one
// subdomain, else every subdomain, merged), with the statistics and the field the mesh must
// honour (the pipeline's own: F on the geometric path).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/pipeline.hpp>

namespace pdd::test {

struct pipeline_run {
  triangle_mesh mesh;
  generate_statistics stats;
  any_sizing sizing; ///< the field the path meshed with (pdd::pipeline::meshing())
};

inline pipeline_run run_pipeline(const pslg& g, const generate_options& o) {
  pipeline<> p(g, o);
  pipeline_run r;
  r.mesh = p.mesh_merged();
  r.stats = p.statistics();
  r.sizing = p.meshing().sizing;
  return r;
}

} // namespace pdd::test
