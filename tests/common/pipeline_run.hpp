// A stepwise pipeline run for the tests: decouple, then mesh (the whole domain when the plan is
// one subdomain, else every subdomain, merged), with the statistics and the field the mesh must
// honour (the pipeline's own: F on the geometric path).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/mesh/merge.hpp>
#include <pdd/pipeline.hpp>

namespace pdd::test {

struct pipeline_run {
  triangle_mesh mesh;
  generate_statistics stats;
  any_sizing sizing; ///< pdd::pipeline::options().sizing after the plan
};

inline pipeline_run run_pipeline(const pslg& g, const generate_options& o) {
  pipeline<> p(g, o);
  p.decouple();
  pipeline_run r;
  if (p.subdomains() <= 1) {
    r.mesh = p.mesh_whole();
  } else {
    merge_sink sink(o.threads);
    p.mesh(sink);
    r.mesh = sink.take();
  }
  r.stats = p.statistics();
  r.sizing = p.options().sizing;
  return r;
}

} // namespace pdd::test
