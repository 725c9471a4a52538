// libpdd: the geometry of pdd::sizing_range over a region (sizing/detail/region_grid.hpp), so
// that the light headers which bound a field need not include CGAL's kernel.
#include <pdd/sizing/detail/region_grid_impl.hpp>
