// libpdd: pdd::native::mesher for the built-in sizing fields, the meshing stages over it (any sink,
// through pdd::mesh_sink_ref), pdd::generate and pdd::pipeline with it (pipeline/compiled.hpp,
// pipeline/generate_templates.hpp, pipeline.hpp).
#include <pdd/pipeline/compiled.hpp>
#include <pdd/pipeline/generate_templates.hpp>

namespace pdd {
PDD_KERNEL_INSTANTIATIONS(template, native::mesher);
PDD_GENERATE_INSTANTIATIONS(template, native::mesher);
template class pipeline<native::mesher, default_partitioner, tbb_executor>;
} // namespace pdd
