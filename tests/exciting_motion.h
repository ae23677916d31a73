#pragma once
// The exciting trajectory of the identification tests: per joint j, the sum of `harmonics` sines
// q_j(t) = Σ_h (A/h)·sin(ω_h·t + φ_jh), ω_h = 2π·0.2·h, φ_jh = a·j + b·h·j + c·h, sampled at
// 100 Hz, with its velocities and accelerations differentiated by hand (dq = Σ (A/h)·ω·cos,
// ddq = −Σ (A/h)·ω²·sin). The torques are left to the caller (sized, not set). And the true
// planar arm those tests simulate.

#include <cmath>

#include "massprops/analysis/identify.h"
#include "massprops/dynamics/kinematic_tree.h"

namespace massprops::test_support {

struct ExcitingMotion {
  int harmonics = 3;
  double amplitude = 0.9;            // A, rad: harmonic h has A / h
  double a = 0.7, b = 1.3, c = 0.4;  // the phases φ_jh = a·j + b·h·j + c·h
};

inline OrderedTrajectory SumOfSines(const ExcitingMotion& motion, int joints, int samples) {
  constexpr double kPi = 3.14159265358979323846;
  OrderedTrajectory data;
  data.q.setZero(samples, joints);
  data.dq.setZero(samples, joints);
  data.ddq.setZero(samples, joints);
  data.tau.resize(samples, joints);
  for (int k = 0; k < samples; ++k) {
    const double t = 0.01 * k;
    for (int j = 0; j < joints; ++j) {
      for (int h = 1; h <= motion.harmonics; ++h) {
        const double w = 2 * kPi * 0.2 * h, phase = motion.a * j + motion.b * h * j + motion.c * h;
        const double amplitude = motion.amplitude / h;
        data.q(k, j) += amplitude * std::sin(w * t + phase);
        data.dq(k, j) += amplitude * w * std::cos(w * t + phase);
        data.ddq(k, j) -= amplitude * w * w * std::sin(w * t + phase);
      }
    }
  }
  return data;
}

// The true arm of tools/make_identify_csv.py (m1 2.3 kg, lc1 0.22 m, I1 0.05 kg·m² about the
// joint axis y; m2 1.0 kg, lc2 0.24 m, I2 0.012 kg·m²; ixx, izz plausible), friction viscous
// only: `file` (testdata/identify/planar_arm*.urdf's tree) with those bodies.
inline KinematicTree TruePlanarArm(const KinematicTree& file) {
  KinematicTree truth = file;
  Eigen::Matrix3d upper = Eigen::Vector3d(0.005, 0.05, 0.05).asDiagonal();
  Eigen::Matrix3d fore = Eigen::Vector3d(0.002, 0.012, 0.012).asDiagonal();
  truth.bodies[0].pi_BBo_B = MakeInertialParameters(2.3, {0.22, 0, 0}, upper);
  truth.bodies[1].pi_BBo_B = MakeInertialParameters(1.0, {0.24, 0, 0}, fore);
  truth.friction = {{0.3, 0, 0, 0}, {0.1, 0, 0, 0}};
  return truth;
}

}  // namespace massprops::test_support
