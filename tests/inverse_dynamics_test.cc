// Inverse dynamics (massprops/dynamics/inverse_dynamics.h) against closed forms derived by hand
// from the Lagrangian, for robots read from URDF text through the model reader: a pendulum (also
// with its joint frame turned by rpy), the two-link planar arm of Spong, Hutchinson and
// Vidyasagar ("Robot Modeling and Control", Wiley 2006, §7.4, the planar elbow manipulator), a
// vertical prismatic joint, and a revolute-prismatic (polar) arm.
#include "massprops/dynamics/inverse_dynamics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "dynamics_test_support.h"

namespace massprops {
namespace {

using test_support::TreeOf;
using test_support::V;
constexpr double kG = 9.81;

std::string Inertial(const std::string& xyz, double mass, const std::string& moments) {
  return test_support::InertialXml(xyz, mass, moments);
}
std::string Joint(const std::string& name, const std::string& type, const std::string& parent,
                  const std::string& child, const std::string& origin, const std::string& axis) {
  return test_support::JointXml(name, type, parent, child, origin, axis);
}

// A pendulum of mass m whose center of mass is l from the hinge along the link's x axis, with
// central moment Iy about the hinge's axis (y). The height of the center of mass is −l·sin q, so
// with V = m·g·z the Lagrangian gives τ = (Iy + m·l²)·q̈ − m·g·l·cos q (hand-derived).
TEST(InverseDynamicsTest, PendulumMatchesItsLagrangian) {
  const double m = 2, l = 0.7, Iy = 0.05;
  const KinematicTree tree =
      TreeOf("<robot name='p'><link name='base'/><link name='arm'>" +
             Inertial("0.7 0 0", m, "ixx='0.01' iyy='0.05' izz='0.04' ixy='0' ixz='0' iyz='0'") +
             "</link>" + Joint("hinge", "continuous", "base", "arm", "xyz='0.1 0.2 1'", "0 1 0") +
             "</robot>");
  ASSERT_EQ(tree.size(), 1);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> any(-3, 3);
  for (int k = 0; k < 20; ++k) {
    const double q = any(rng), dq = any(rng), ddq = any(rng);
    const double expected = (Iy + m * l * l) * ddq - m * kG * l * std::cos(q);
    const Eigen::VectorXd tau = CalcInverseDynamics(tree, V({q}), V({dq}), V({ddq}));
    EXPECT_NEAR(tau(0), expected, 1e-13 * (std::abs(expected) + m * kG * l)) << "q " << q;
  }
}

// The same pendulum with the joint frame turned by rpy = (π/2, 0, 0) and the axis z of that
// frame: Rx(π/2)·z = −y, so the hinge turns about the base's −y and the center of mass rises:
// z = +l·sin q, τ = (Iz + m·l²)·q̈ + m·g·l·cos q, Iz the link's moment about its own z.
TEST(InverseDynamicsTest, PendulumWithARotatedJointFrameTurnsTheOtherWay) {
  const double m = 2, l = 0.7, Iz = 0.04;
  const KinematicTree tree =
      TreeOf("<robot name='p'><link name='base'/><link name='arm'>" +
             Inertial("0.7 0 0", m, "ixx='0.01' iyy='0.05' izz='0.04' ixy='0' ixz='0' iyz='0'") +
             "</link>" +
             Joint("hinge", "revolute", "base", "arm", "xyz='0 0 1' rpy='1.5707963267948966 0 0'",
                   "0 0 1") +
             "</robot>");
  for (double q : {-1.0, 0.0, 0.4, 2.0}) {
    const double ddq = 0.3 - q;
    const double expected = (Iz + m * l * l) * ddq + m * kG * l * std::cos(q);
    const Eigen::VectorXd tau = CalcInverseDynamics(tree, V({q}), V({1.5}), V({ddq}));
    EXPECT_NEAR(tau(0), expected, 1e-12) << "q " << q;
  }
}

// Spong, Hutchinson and Vidyasagar 2006, §7.4 (planar elbow manipulator), gravity along −y:
//   d11 = m1·lc1² + m2·(l1² + lc2² + 2·l1·lc2·cos q2) + I1 + I2
//   d12 = m2·(lc2² + l1·lc2·cos q2) + I2,   d22 = m2·lc2² + I2,   h = −m2·l1·lc2·sin q2
//   τ1 = d11·q̈1 + d12·q̈2 + 2h·q̇1·q̇2 + h·q̇2² + (m1·lc1 + m2·l1)·g·cos q1 + m2·lc2·g·cos(q1+q2)
//   τ2 = d12·q̈1 + d22·q̈2 − h·q̇1² + m2·lc2·g·cos(q1+q2)
// I1, I2 the central moments about z; the links' other moments and products must not matter.
TEST(InverseDynamicsTest, TwoLinkPlanarArmMatchesSpongHutchinsonVidyasagar) {
  const double m1 = 3, m2 = 2, l1 = 0.8, lc1 = 0.35, lc2 = 0.3, I1 = 0.12, I2 = 0.07;
  KinematicTree tree = TreeOf(
      "<robot name='elbow'><link name='base'/><link name='upper'>" +
      Inertial("0.35 0 0", m1, "ixx='0.03' iyy='0.11' izz='0.12' ixy='0.004' ixz='0.002' iyz='0'") +
      "</link><link name='fore'>" +
      Inertial("0.3 0 0", m2, "ixx='0.02' iyy='0.06' izz='0.07' ixy='0' ixz='0.001' iyz='0.003'") +
      "</link>" + Joint("shoulder", "revolute", "base", "upper", "xyz='0 0 0'", "0 0 1") +
      Joint("elbow", "revolute", "upper", "fore", "xyz='0.8 0 0'", "0 0 1") + "</robot>");
  tree.gravity_base = Eigen::Vector3d(0, -kG, 0);
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> any(-3, 3);
  for (int k = 0; k < 50; ++k) {
    const double q1 = any(rng), q2 = any(rng), dq1 = any(rng), dq2 = any(rng), ddq1 = any(rng),
                 ddq2 = any(rng);
    const double d11 =
        m1 * lc1 * lc1 + m2 * (l1 * l1 + lc2 * lc2 + 2 * l1 * lc2 * std::cos(q2)) + I1 + I2;
    const double d12 = m2 * (lc2 * lc2 + l1 * lc2 * std::cos(q2)) + I2;
    const double d22 = m2 * lc2 * lc2 + I2;
    const double h = -m2 * l1 * lc2 * std::sin(q2);
    const double g2 = m2 * lc2 * kG * std::cos(q1 + q2);
    const double tau1 = d11 * ddq1 + d12 * ddq2 + 2 * h * dq1 * dq2 + h * dq2 * dq2 +
                        (m1 * lc1 + m2 * l1) * kG * std::cos(q1) + g2;
    const double tau2 = d12 * ddq1 + d22 * ddq2 - h * dq1 * dq1 + g2;
    const Eigen::VectorXd tau =
        CalcInverseDynamics(tree, V({q1, q2}), V({dq1, dq2}), V({ddq1, ddq2}));
    EXPECT_NEAR(tau(0), tau1, 1e-12 * 100);
    EXPECT_NEAR(tau(1), tau2, 1e-12 * 100);
  }
}

// A vertical slider of mass m: τ = m·(q̈ + g); with its joint frame upside down (rpy = (π, 0, 0),
// the axis z of the frame is the base's −z): τ = m·(q̈ − g). Hand-derived (Newton).
TEST(InverseDynamicsTest, VerticalPrismaticJointLiftsItsMass) {
  const double m = 4.5;
  for (const char* rpy : {"0 0 0", "3.141592653589793 0 0"}) {
    const double sign = std::string(rpy) == "0 0 0" ? 1 : -1;
    const KinematicTree tree = TreeOf(
        "<robot name='s'><link name='base'/><link name='slider'>" +
        Inertial("0.1 -0.2 0.3", m, "ixx='0.1' iyy='0.2' izz='0.25' ixy='0' ixz='0' iyz='0'") +
        "</link>" +
        Joint("lift", "prismatic", "base", "slider",
              std::string("xyz='0.3 0 0.5' rpy='") + rpy + "'", "0 0 1") +
        "</robot>");
    for (double ddq : {-2.0, 0.0, 1.25}) {
      const Eigen::VectorXd tau = CalcInverseDynamics(tree, V({0.4}), V({-0.7}), V({ddq}));
      EXPECT_NEAR(tau(0), m * (ddq + sign * kG), 1e-12) << rpy;
    }
  }
}

// A revolute joint about the vertical z carrying a prismatic joint along its x (polar arm,
// r = q2). The Lagrangian L = ½(Iz1 + Iz2 + m2·r²)·θ̇² + ½·m2·ṙ² (gravity does no work) gives
//   τθ = (Iz1 + Iz2 + m2·r²)·θ̈ + 2·m2·r·ṙ·θ̇,   τr = m2·(r̈ − r·θ̇²)   (hand-derived).
TEST(InverseDynamicsTest, PolarArmShowsCentripetalAndCoriolisTerms) {
  const double Iz1 = 0.2, Iz2 = 0.03, m2 = 1.5;
  const KinematicTree tree =
      TreeOf("<robot name='polar'><link name='base'/><link name='turret'>" +
             Inertial("0 0 0", 4, "ixx='0.3' iyy='0.3' izz='0.2' ixy='0' ixz='0' iyz='0'") +
             "</link><link name='boom'>" +
             Inertial("0 0 0", m2, "ixx='0.01' iyy='0.02' izz='0.03' ixy='0' ixz='0' iyz='0'") +
             "</link>" + Joint("turn", "continuous", "base", "turret", "xyz='0 0 0.2'", "0 0 1") +
             Joint("reach", "prismatic", "turret", "boom", "xyz='0 0 0'", "1 0 0") + "</robot>");
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> any(-2, 2);
  for (int k = 0; k < 20; ++k) {
    const double th = any(rng), r = any(rng), dth = any(rng), dr = any(rng), ddth = any(rng),
                 ddr = any(rng);
    const Eigen::VectorXd tau = CalcInverseDynamics(tree, V({th, r}), V({dth, dr}), V({ddth, ddr}));
    EXPECT_NEAR(tau(0), (Iz1 + Iz2 + m2 * r * r) * ddth + 2 * m2 * r * dr * dth, 1e-12);
    EXPECT_NEAR(tau(1), m2 * (ddr - r * dth * dth), 1e-12);
  }
}

// τ += viscous·q̇ + coulomb·sign(q̇) + offset + armature·q̈ (kinematic_tree.h), sign(0) = 0.
TEST(InverseDynamicsTest, FrictionAndArmatureAddTheirTerms) {
  KinematicTree tree = TreeOf(
      "<robot name='p'><link name='base'/><link name='arm'>" +
      Inertial("0 0 0", 1, "ixx='0.1' iyy='0.1' izz='0.1' ixy='0' ixz='0' iyz='0'") + "</link>" +
      Joint("hinge", "continuous", "base", "arm", "xyz='0 0 0'", "0 0 1") + "</robot>");
  tree.friction[0] = JointFriction{0.5, 0.25, -0.125, 0.03};
  // About the vertical axis through the center of mass: gravity gives no torque, I = 0.1.
  EXPECT_NEAR(CalcInverseDynamics(tree, V({1}), V({2}), V({3}))(0),
              0.1 * 3 + 0.5 * 2 + 0.25 - 0.125 + 0.03 * 3, 1e-15);
  EXPECT_NEAR(CalcInverseDynamics(tree, V({1}), V({-2}), V({3}))(0),
              0.1 * 3 - 0.5 * 2 - 0.25 - 0.125 + 0.03 * 3, 1e-15);
  EXPECT_NEAR(CalcInverseDynamics(tree, V({1}), V({0}), V({0}))(0), -0.125, 1e-15);
}

TEST(InverseDynamicsTest, WrongSizesThrow) {
  const KinematicTree tree = TreeOf(
      "<robot name='p'><link name='base'/><link name='arm'>" +
      Inertial("0 0 0", 1, "ixx='0.1' iyy='0.1' izz='0.1' ixy='0' ixz='0' iyz='0'") + "</link>" +
      Joint("hinge", "continuous", "base", "arm", "xyz='0 0 0'", "0 0 1") + "</robot>");
  EXPECT_THROW(CalcInverseDynamics(tree, V({1, 2}), V({0}), V({0})), std::invalid_argument);
  EXPECT_THROW(CalcInverseDynamics(tree, Eigen::VectorXd::Zero(9), V({1}), V({0}), V({0})),
               std::invalid_argument);
}

}  // namespace
}  // namespace massprops
