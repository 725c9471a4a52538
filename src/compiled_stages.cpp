// libpdd: the decomposition stages (MADD, Algorithm 7.1, the geometric loop; the decoupling
// path) with the default partitioner and the TBB executor (pipeline/compiled.hpp).
#include <pdd/pipeline/compiled.hpp>

namespace pdd {
PDD_STAGE_INSTANTIATIONS(template);
} // namespace pdd
