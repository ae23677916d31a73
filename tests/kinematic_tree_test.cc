// The kinematic tree of a Model (massprops/dynamics/kinematic_tree.h): the 10 inertial
// parameters against the core classes (SpatialInertia's own shift and re-expression, a second
// computation of the same numbers), welding by fixed joints against hand-derived sums, and the
// models that are no fixed-base tree.
#include "massprops/dynamics/kinematic_tree.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>
#include <string>

#include "dynamics_test_support.h"

namespace massprops {
namespace {

using test_support::InertialXml;
using test_support::JointXml;

Eigen::Matrix3d RandomRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

// A valid central inertia: principal moments of a random box, turned by a random rotation.
Eigen::Matrix3d RandomCentralInertia(std::mt19937_64& rng, double mass) {
  std::uniform_real_distribution<double> side(0.05, 0.5);
  const double a = side(rng), b = side(rng), c = side(rng);
  const Eigen::Vector3d moments =
      mass / 12 * Eigen::Vector3d(b * b + c * c, a * a + c * c, a * a + b * b);
  const Eigen::Matrix3d R = RandomRotation(rng);
  return R * moments.asDiagonal() * R.transpose();
}

TEST(KinematicTreeTest, ParametersMatchSpatialInertiaMadeFromTheCentralInertia) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> any(-0.5, 0.5);
  for (int k = 0; k < 100; ++k) {
    const double mass = 0.1 + 5 * (any(rng) + 0.5);
    const Eigen::Vector3d c(any(rng), any(rng), any(rng));
    const Eigen::Matrix3d I_c = RandomCentralInertia(rng, mass);
    const InertialParameters pi = MakeInertialParameters(mass, c, I_c);
    const SpatialInertia<double> M = SpatialInertia<double>::MakeFromCentralInertia(
        mass, c,
        RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(
            I_c(0, 0), I_c(1, 1), I_c(2, 2), I_c(0, 1), I_c(0, 2), I_c(1, 2), true));
    const InertialParameters from_core = MakeInertialParameters(M);
    EXPECT_LT((pi - from_core).norm(), 1e-14 * pi.norm());
    // And back: ToSpatialInertia gives the same mass, center of mass and inertia about Bo.
    const SpatialInertia<double> back = ToSpatialInertia(pi);
    EXPECT_NEAR(back.get_mass(), mass, 1e-15 * mass);
    EXPECT_LT((back.get_com() - c).norm(), 1e-14);
    EXPECT_LT((back.CalcRotationalInertia().CopyToFullMatrix3() -
               M.CalcRotationalInertia().CopyToFullMatrix3())
                  .norm(),
              1e-14 * pi.norm());
  }
}

TEST(KinematicTreeTest, ReExpressedParametersMatchSpatialInertiaShiftAndReExpress) {
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> any(-0.5, 0.5);
  for (int k = 0; k < 100; ++k) {
    const double mass = 0.1 + 5 * (any(rng) + 0.5);
    const Eigen::Vector3d c(any(rng), any(rng), any(rng));
    const Eigen::Matrix3d I_c = RandomCentralInertia(rng, mass);
    const Pose X_BC{Eigen::Vector3d(any(rng), any(rng), any(rng)), RandomRotation(rng)};
    const InertialParameters pi_B =
        ReExpressInertialParameters(MakeInertialParameters(mass, c, I_c), X_BC);
    // The core: the body about Co in C, re-expressed in B, then shifted from Co to Bo
    // (p_CoBo_B = −p_BC).
    const SpatialInertia<double> M_CCo_C = SpatialInertia<double>::MakeFromCentralInertia(
        mass, c,
        RotationalInertia<double>::MakeFromMomentsAndProductsOfInertia(
            I_c(0, 0), I_c(1, 1), I_c(2, 2), I_c(0, 1), I_c(0, 2), I_c(1, 2), true));
    const SpatialInertia<double> M_BBo_B = M_CCo_C.ReExpress(X_BC.R_AB).Shift(-X_BC.p_AB);
    EXPECT_LT((pi_B - MakeInertialParameters(M_BBo_B)).norm(), 1e-13 * pi_B.norm()) << k;
  }
}

// Hand-derived: a body link 'a' (1 kg at its origin, central diag(0.01, 0.02, 0.03)) carries
// link 'b' by a fixed joint at (0.5, 0, 0) turned by yaw π/2; b has 2 kg at its origin, central
// diag(0.1, 0.2, 0.3) in b, which is diag(0.2, 0.1, 0.3) in a (x and y swap). About a's origin:
// m = 3, h = 2·(0.5, 0, 0) = (1, 0, 0), I = diag(0.01 + 0.2, 0.02 + 0.1 + 2·0.25,
// 0.03 + 0.3 + 2·0.25) = diag(0.21, 0.62, 0.83).
TEST(KinematicTreeTest, FixedJointsWeldLinksIntoTheBodyTheyRideOn) {
  const KinematicTree tree = test_support::TreeOf(
      "<robot name='w'><link name='base'/><link name='plate'>" +
      InertialXml("0 0 0", 5, "ixx='1' iyy='1' izz='1' ixy='0' ixz='0' iyz='0'") +
      "</link><link name='a'>" +
      InertialXml("0 0 0", 1, "ixx='0.01' iyy='0.02' izz='0.03' ixy='0' ixz='0' iyz='0'") +
      "</link><link name='b'>" +
      InertialXml("0 0 0", 2, "ixx='0.1' iyy='0.2' izz='0.3' ixy='0' ixz='0' iyz='0'") +
      "</link><link name='tip'/>" +
      JointXml("bolt", "fixed", "base", "plate", "xyz='0 0 0.1'", "1 0 0") +
      JointXml("hinge", "revolute", "plate", "a", "xyz='0 0 0.2'", "0 0 2") +
      JointXml("weld", "fixed", "a", "b", "xyz='0.5 0 0' rpy='0 0 1.5707963267948966'", "1 0 0") +
      JointXml("tip_weld", "fixed", "b", "tip", "xyz='0 0 0'", "1 0 0") + "</robot>");
  ASSERT_EQ(tree.size(), 1);
  EXPECT_EQ(tree.base_link, "base");
  EXPECT_EQ(tree.base_welded_links, std::vector<std::string>{"plate"});
  const MovingBody& body = tree.bodies[0];
  EXPECT_EQ(body.link, "a");
  EXPECT_EQ(body.joint, "hinge");
  EXPECT_EQ(body.parent, -1);
  EXPECT_EQ(body.welded_links, (std::vector<std::string>{"b", "tip"}));
  // The joint frame in the base: through the bolt (0.1 up) and the hinge (0.2 up).
  EXPECT_LT((body.X_PB0.p_AB - Eigen::Vector3d(0, 0, 0.3)).norm(), 1e-15);
  EXPECT_LT((body.axis_B - Eigen::Vector3d::UnitZ()).norm(), 1e-15);  // normalized
  InertialParameters expected;
  expected << 3, 1, 0, 0, 0.21, 0, 0.62, 0, 0, 0.83;
  EXPECT_LT((body.pi_BBo_B - expected).norm(), 1e-15) << body.pi_BBo_B.transpose();
  EXPECT_EQ(tree.friction.size(), 1u);
}

TEST(KinematicTreeTest, ParentsComeBeforeTheirChildren) {
  const KinematicTree tree = test_support::TreeOf(
      "<robot name='y'><link name='base'/><link name='l1'/><link name='l2'/><link name='r1'/>"
      "<link name='r2'/>" +
      JointXml("j_r2", "revolute", "r1", "r2", "xyz='0 0 0'", "1 0 0") +
      JointXml("j_l1", "revolute", "base", "l1", "xyz='0 0 0'", "1 0 0") +
      JointXml("j_r1", "prismatic", "base", "r1", "xyz='0 0 0'", "1 0 0") +
      JointXml("j_l2", "continuous", "l1", "l2", "xyz='0 0 0'", "1 0 0") + "</robot>");
  ASSERT_EQ(tree.size(), 4);
  for (int i = 0; i < tree.size(); ++i)
    EXPECT_LT(tree.bodies[static_cast<std::size_t>(i)].parent, i);
  EXPECT_EQ(tree.bodies[static_cast<std::size_t>(tree.FindJoint("j_r1"))].type,
            MovingBody::JointType::kPrismatic);
  EXPECT_EQ(tree.FindJoint("nope"), -1);
  EXPECT_EQ(tree.JointNames().size(), 4u);
}

TEST(KinematicTreeTest, AFloatingJointIsNoFixedBaseTree) {
  const ReadResult read = ReadModelString(
      "<robot name='f'><link name='base'/><link name='a'/>" +
          JointXml("free", "floating", "base", "a", "xyz='0 0 0'", "1 0 0") + "</robot>",
      "f.urdf");
  ASSERT_TRUE(read.ok());
  const KinematicTreeResult made = MakeKinematicTree(read.models[0]);
  EXPECT_FALSE(made.tree.has_value());
  EXPECT_NE(made.error.find("joint 'free' is of type 'floating'"), std::string::npos) << made.error;
}

TEST(KinematicTreeTest, ALinkNotAttachedToTheRootIsNamed) {
  Model model;
  model.root_link = "base";
  model.links.resize(2);
  model.links[0].name = "base";
  model.links[1].name = "loose";
  const KinematicTreeResult made = MakeKinematicTree(model);
  EXPECT_FALSE(made.tree.has_value());
  EXPECT_NE(made.error.find("link 'loose' is not attached"), std::string::npos) << made.error;
}

TEST(KinematicTreeTest, AnUnreadableInertialIsNamed) {
  Model model;
  model.root_link = "base";
  model.links.resize(2);
  model.links[0].name = "base";
  model.links[1].name = "arm";
  model.links[1].inertial_unreadable = true;
  model.joints.resize(1);
  model.joints[0].name = "j";
  model.joints[0].type = Joint::Type::kRevolute;
  model.joints[0].parent = "base";
  model.joints[0].child = "arm";
  const KinematicTreeResult made = MakeKinematicTree(model);
  EXPECT_FALSE(made.tree.has_value());
  EXPECT_NE(made.error.find("link 'arm' could not be read"), std::string::npos) << made.error;
}

TEST(KinematicTreeTest, SdfJointsToTheWorldMakeTheWorldTheBase) {
  const ReadResult read = ReadModelString(
      "<sdf version='1.9'><model name='m'>"
      "<link name='arm'><pose>0 0 1 0 0 0</pose><inertial><mass>2</mass></inertial></link>"
      "<joint name='hinge' type='revolute'><parent>world</parent><child>arm</child>"
      "<axis><xyz>0 1 0</xyz></axis></joint></model></sdf>",
      "m.sdf");
  ASSERT_TRUE(read.ok()) << read.errors[0].ToString();
  const KinematicTreeResult made = MakeKinematicTree(read.models[0]);
  ASSERT_TRUE(made.tree.has_value()) << made.error;
  EXPECT_EQ(made.tree->base_link, "world");
  ASSERT_EQ(made.tree->size(), 1);
  EXPECT_LT((made.tree->bodies[0].X_PB0.p_AB - Eigen::Vector3d(0, 0, 1)).norm(), 1e-15);
  EXPECT_LT((made.tree->bodies[0].axis_B - Eigen::Vector3d::UnitY()).norm(), 1e-15);
}

}  // namespace
}  // namespace massprops
