// libpdd: pdd::cgal::mesher for the built-in sizing fields, the meshing stages over it (any sink,
// through pdd::mesh_sink_ref), pdd::generate and pdd::pipeline with it (pipeline/compiled.hpp,
// pipeline/generate_templates.hpp, pipeline.hpp).
#include <pdd/pipeline/compiled.hpp>
#include <pdd/pipeline/generate_templates.hpp>

namespace pdd {
PDD_KERNEL_INSTANTIATIONS(template, cgal::mesher);
PDD_GENERATE_INSTANTIATIONS(template, cgal::mesher);
template class pipeline<cgal::mesher, default_partitioner, tbb_executor>;
} // namespace pdd
