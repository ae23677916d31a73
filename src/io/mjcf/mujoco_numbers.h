#pragma once
// MuJoCo's numerical thresholds that the MJCF reader reproduces, once for all its units (a unity
// build compiles several of them as one): mjMINVAL and mjEPS of MuJoCo's mjmodel.h.

namespace massprops {
namespace mjcf {

inline constexpr double kMjMinVal = 1e-15;  // mjMINVAL: below it, a mass, volume or length is 0
inline constexpr double kMjEps = 1e-14;     // mjEPS: below it, a vector has no direction

}  // namespace mjcf
}  // namespace massprops
