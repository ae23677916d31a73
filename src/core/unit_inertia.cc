/// @file
/// Explicit instantiations of UnitInertia<T> for float, double and long double (the definitions are
/// in include/massprops/core/unit_inertia.h).

#include "massprops/core/unit_inertia.h"

namespace massprops {

template class UnitInertia<float>;
template class UnitInertia<double>;
template class UnitInertia<long double>;

}  // namespace massprops
