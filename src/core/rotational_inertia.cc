/// @file
/// Explicit instantiations of RotationalInertia<T> for float, double and long double (the
/// definitions are in include/massprops/core/rotational_inertia.h).

#include "massprops/core/rotational_inertia.h"

namespace massprops {

template class RotationalInertia<float>;
template class RotationalInertia<double>;
template class RotationalInertia<long double>;

}  // namespace massprops
