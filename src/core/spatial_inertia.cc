/// @file
/// Explicit instantiations of SpatialInertia<T> for float, double and long double (the definitions
/// are in include/massprops/core/spatial_inertia.h).

#include "massprops/core/spatial_inertia.h"

namespace massprops {

template class SpatialInertia<float>;
template class SpatialInertia<double>;
template class SpatialInertia<long double>;

}  // namespace massprops
