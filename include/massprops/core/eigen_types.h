#pragma once
/// @file
/// Short names for the fixed-size Eigen types that massprops uses throughout.

#include <Eigen/Core>

namespace massprops {

template <typename T>
using Vector3 = Eigen::Matrix<T, 3, 1>;
template <typename T>
using Matrix3 = Eigen::Matrix<T, 3, 3>;
template <typename T>
using Matrix4 = Eigen::Matrix<T, 4, 4>;

}  // namespace massprops
