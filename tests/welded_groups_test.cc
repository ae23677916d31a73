#include "massprops/analysis/welded_groups.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace massprops {
namespace {

constexpr double kTol = 1e-12;

Link MakeLink(const std::string& name, double mass, double ixx, double iyy, double izz,
              const Eigen::Vector3d& p_BoBcm = Eigen::Vector3d::Zero()) {
  Link link;
  link.name = name;
  Inertial inertial;
  inertial.mass = mass;
  inertial.ixx = ixx;
  inertial.iyy = iyy;
  inertial.izz = izz;
  inertial.X_BBi.p_AB = p_BoBcm;
  link.inertial = inertial;
  return link;
}

Link MakeFrame(const std::string& name) {
  Link link;
  link.name = name;
  return link;
}

Joint MakeJoint(const std::string& name, Joint::Type type, const std::string& parent,
                const std::string& child, const Pose& X_PC = Pose()) {
  Joint joint;
  joint.name = name;
  joint.type = type;
  joint.type_name = type == Joint::Type::kFixed ? "fixed" : "revolute";
  joint.parent = parent;
  joint.child = child;
  joint.X_PC = X_PC;
  return joint;
}

Eigen::Matrix3d RotZ(double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// Hand-derived with the box formula I = m/12·(b²+c², a²+c², a²+b²) and the parallel axis theorem:
// box A (1 kg, 0.2 × 0.1 × 0.1 m) at the root origin: I_A = (0.02, 0.05, 0.05)/12.
// box B (2 kg, 0.1 × 0.3 × 0.1 m): I_B = 2/12·(0.10, 0.02, 0.10) = (1/60, 1/300, 1/60), welded at
// x = 0.5 m and turned 90° about z, so B's y axis is A's −x axis: in A, I_B = (1/300, 1/60, 1/60).
// Composite: mass 3, com x = 2·0.5/3 = 1/3. Shifts away from each com: A is 1/3 from it (adds
// 1·1/9 to Iyy, Izz), B is 1/6 from it (adds 2/36 = 1/18). Central:
// Ixx = 1/600 + 1/300 = 0.005; Iyy = Izz = 0.05/12 + 1/60 + 1/9 + 1/18 = 0.1875.
TEST(WeldedGroupsTest, TwoBoxesWeldedAtAnOffsetAndARotationComposeByTheParallelAxisTheorem) {
  Model model;
  model.root_link = "a";
  model.links.push_back(MakeLink("a", 1, 0.02 / 12, 0.05 / 12, 0.05 / 12));
  model.links.push_back(MakeLink("b", 2, 0.10 / 6, 0.02 / 6, 0.10 / 6));
  Pose X_AB;
  X_AB.p_AB = Eigen::Vector3d(0.5, 0, 0);
  X_AB.R_AB = RotZ(M_PI / 2);
  model.joints.push_back(MakeJoint("weld", Joint::Type::kFixed, "a", "b", X_AB));

  const std::vector<WeldedGroup> groups = FindWeldedGroups(model);
  ASSERT_EQ(groups.size(), 1u);
  const CompositeInertia c = CalcCompositeInertia(model, groups[0]);
  EXPECT_NEAR(c.mass, 3, kTol);
  EXPECT_NEAR(c.p_RoScm_R.x(), 1.0 / 3, kTol);
  EXPECT_NEAR(c.p_RoScm_R.y(), 0, kTol);
  EXPECT_NEAR(c.p_RoScm_R.z(), 0, kTol);
  EXPECT_NEAR(c.I_SScm_R(0, 0), 0.005, kTol);
  EXPECT_NEAR(c.I_SScm_R(1, 1), 0.1875, kTol);
  EXPECT_NEAR(c.I_SScm_R(2, 2), 0.1875, kTol);
  EXPECT_NEAR(c.I_SScm_R(0, 1), 0, kTol);
  EXPECT_NEAR(c.I_SScm_R(0, 2), 0, kTol);
  EXPECT_NEAR(c.I_SScm_R(1, 2), 0, kTol);
  // About the root origin: Iyy = 0.05/12 + (1/60 + 2·0.5²) = 0.520833... (each box shifted from
  // its own com straight to the origin), which is also 0.1875 + 3·(1/3)².
  const Eigen::Matrix3d I_Ro = c.CalcInertiaAboutOrigin();
  EXPECT_NEAR(I_Ro(1, 1), 0.05 / 12 + 1.0 / 60 + 0.5, kTol);
  EXPECT_NEAR(I_Ro(2, 2), 0.05 / 12 + 1.0 / 60 + 0.5, kTol);
  EXPECT_NEAR(I_Ro(0, 0), 0.005, kTol);
  // The same numbers through the core class.
  const SpatialInertia<double> M = c.CalcSpatialInertia();
  EXPECT_NEAR(M.get_mass(), 3, kTol);
  EXPECT_NEAR(M.get_com().x(), 1.0 / 3, kTol);
}

// A chain a -fixed- b -revolute- c -fixed- d -fixed- e, with e listed before c in the file:
// two groups {a, b} (the model root, not moving) and {c, d, e} (moving on the revolute joint),
// each root first.
TEST(WeldedGroupsTest, FixedJointsPartitionAChainIntoGroupsOrderedByRootFileOrder) {
  Model model;
  model.root_link = "a";
  for (const char* name : {"a", "b", "e", "c", "d"}) model.links.push_back(MakeFrame(name));
  model.joints.push_back(MakeJoint("ab", Joint::Type::kFixed, "a", "b"));
  model.joints.push_back(MakeJoint("bc", Joint::Type::kRevolute, "b", "c"));
  model.joints.push_back(MakeJoint("de", Joint::Type::kFixed, "d", "e"));
  model.joints.push_back(MakeJoint("cd", Joint::Type::kFixed, "c", "d"));
  const std::vector<WeldedGroup> groups = FindWeldedGroups(model);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].root_link, "a");
  EXPECT_EQ(groups[0].links, (std::vector<int>{0, 1}));
  EXPECT_EQ(groups[0].parent_joint, -1);
  EXPECT_FALSE(groups[0].is_moving);
  EXPECT_EQ(groups[1].root_link, "c");
  EXPECT_EQ(groups[1].links, (std::vector<int>{3, 2, 4}));  // c (root), then e, d in file order
  EXPECT_EQ(groups[1].parent_joint, 1);
  EXPECT_TRUE(groups[1].is_moving);
}

// A free SDF link (no joint, not the root) floats: it is a moving group of its own.
TEST(WeldedGroupsTest, ALinkWithoutJointThatIsNotTheRootIsFreeFloating) {
  Model model;
  model.format = Model::Format::kSdf;
  model.root_link = "a";
  model.links.push_back(MakeFrame("a"));
  model.links.push_back(MakeFrame("floating"));
  const std::vector<WeldedGroup> groups = FindWeldedGroups(model);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_FALSE(groups[0].is_moving);
  EXPECT_TRUE(groups[1].is_moving);
  EXPECT_EQ(groups[1].parent_joint, -1);
}

// 100 000 links of 1 kg, each welded 0.01 m along x from the previous one: one group, mass
// 100 000, com at the mean position 0.01·(n − 1)/2 (arithmetic series); no recursion, so no stack
// overflow, and linear time.
TEST(WeldedGroupsTest, AHundredThousandLinkFixedChainIsOneGroupComputedInLinearTime) {
  constexpr int n = 100000;
  Model model;
  model.root_link = "l0";
  model.links.reserve(n);
  model.joints.reserve(n);
  Pose X;
  X.p_AB = Eigen::Vector3d(0.01, 0, 0);
  for (int i = 0; i < n; ++i) {
    model.links.push_back(MakeLink("l" + std::to_string(i), 1, 0, 0, 0));
    if (i > 0) {
      model.joints.push_back(MakeJoint("j" + std::to_string(i), Joint::Type::kFixed,
                                       "l" + std::to_string(i - 1), "l" + std::to_string(i), X));
    }
  }
  const auto start = std::chrono::steady_clock::now();
  const std::vector<WeldedGroup> groups = FindWeldedGroups(model);
  ASSERT_EQ(groups.size(), 1u);
  ASSERT_EQ(groups[0].links.size(), static_cast<size_t>(n));
  const CompositeInertia c = CalcCompositeInertia(model, groups[0]);
  const ModelCompositeInertia whole = CalcModelCompositeInertia(model);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_NEAR(c.mass, n, 1e-6);
  EXPECT_NEAR(c.p_RoScm_R.x(), 0.01 * (n - 1) / 2, 1e-6);
  EXPECT_NEAR(whole.inertia.p_RoScm_R.x(), 0.01 * (n - 1) / 2, 1e-6);
  EXPECT_TRUE(whole.unreachable_links.empty());
  // Point masses on the x axis: Iyy = Σ (x_i − x̄)² = 0.01²·n(n² − 1)/12 (variance of 0..n−1).
  const double expected = 1e-4 * n * (static_cast<double>(n) * n - 1) / 12;
  EXPECT_NEAR(c.I_SScm_R(1, 1) / expected, 1, 1e-9);
  EXPECT_NEAR(c.I_SScm_R(0, 0), 0, 1e-9);
  RecordProperty("seconds", std::to_string(seconds));
#ifdef NDEBUG
  // Generous (the machine is shared): the linear work takes about 0.1 s in Release. Debug and
  // sanitizer builds are not timed.
  EXPECT_LT(seconds, 10.0);
#endif
}

// Massless members (a tool frame, a massless link with an inertial of zeros) change nothing.
TEST(WeldedGroupsTest, ZeroMassMembersLeaveTheCompositeUnchanged) {
  Model model;
  model.root_link = "body";
  model.links.push_back(MakeLink("body", 2, 0.1, 0.2, 0.25, Eigen::Vector3d(0.1, 0, 0)));
  model.links.push_back(MakeFrame("tool0"));
  model.links.push_back(MakeLink("flange", 0, 0, 0, 0, Eigen::Vector3d(5, 5, 5)));
  Pose X;
  X.p_AB = Eigen::Vector3d(1, 2, 3);
  model.joints.push_back(MakeJoint("t", Joint::Type::kFixed, "body", "tool0", X));
  model.joints.push_back(MakeJoint("f", Joint::Type::kFixed, "tool0", "flange", X));
  const std::vector<WeldedGroup> groups = FindWeldedGroups(model);
  ASSERT_EQ(groups.size(), 1u);
  const CompositeInertia c = CalcCompositeInertia(model, groups[0]);
  EXPECT_EQ(c.mass, 2);
  EXPECT_NEAR(c.p_RoScm_R.x(), 0.1, kTol);
  EXPECT_NEAR(c.I_SScm_R(0, 0), 0.1, kTol);
  EXPECT_NEAR(c.I_SScm_R(1, 1), 0.2, kTol);
  EXPECT_NEAR(c.I_SScm_R(2, 2), 0.25, kTol);
  // The pose of the flange in the root: two 0.5-free translations (1, 2, 3) composed.
  EXPECT_TRUE(groups[0].X_RL[2].p_AB.isApprox(Eigen::Vector3d(2, 4, 6)));
}

// An inertial turned 90° about z: I_B = R·diag(1, 2, 3)·Rᵀ = diag(2, 1, 3) (x and y swap).
TEST(WeldedGroupsTest, LinkMassPropertiesReExpressTheInertialFrameInTheLinkFrame) {
  Link link = MakeLink("l", 1, 1, 2, 3, Eigen::Vector3d(0.1, 0.2, 0.3));
  link.inertial->X_BBi.R_AB = RotZ(M_PI / 2);
  const MassProperties p = LinkMassProperties(link);
  EXPECT_NEAR(p.I_SScm_F(0, 0), 2, kTol);
  EXPECT_NEAR(p.I_SScm_F(1, 1), 1, kTol);
  EXPECT_NEAR(p.I_SScm_F(2, 2), 3, kTol);
  EXPECT_NEAR(p.I_SScm_F(0, 1), 0, kTol);
  EXPECT_TRUE(p.p_FoScm_F.isApprox(Eigen::Vector3d(0.1, 0.2, 0.3)));
  // SDF specification: a link without <inertial> has mass 1 and inertia diag(1, 1, 1); URDF: 0.
  const Link bare = MakeFrame("bare");
  EXPECT_EQ(LinkMassProperties(bare, Model::Format::kSdf).mass, 1);
  EXPECT_EQ(LinkMassProperties(bare, Model::Format::kSdf).I_SScm_F(2, 2), 1);
  EXPECT_EQ(LinkMassProperties(bare).mass, 0);
}

// Zero configuration: a 1 kg point mass at the child's origin, the child 1 m along y from the
// root through a revolute joint, a 1 kg point mass at the root origin: com (0, 0.5, 0),
// Ixx = Izz = 2·0.5² = 0.5 (hand-derived). A link with no path from the root is left out.
TEST(WeldedGroupsTest, ModelCompositeIsTakenAtTheZeroConfigurationInTheRootFrame) {
  Model model;
  model.root_link = "root";
  model.links.push_back(MakeLink("root", 1, 0, 0, 0));
  model.links.push_back(MakeLink("child", 1, 0, 0, 0));
  model.links.push_back(MakeLink("loose", 7, 1, 1, 1));
  Pose X;
  X.p_AB = Eigen::Vector3d(0, 1, 0);
  X.R_AB = RotZ(0.3);
  model.joints.push_back(MakeJoint("j", Joint::Type::kRevolute, "root", "child", X));
  const ModelCompositeInertia whole = CalcModelCompositeInertia(model);
  EXPECT_EQ(whole.inertia.mass, 2);
  EXPECT_TRUE(whole.inertia.p_RoScm_R.isApprox(Eigen::Vector3d(0, 0.5, 0)));
  EXPECT_NEAR(whole.inertia.I_SScm_R(0, 0), 0.5, kTol);
  EXPECT_NEAR(whole.inertia.I_SScm_R(1, 1), 0, kTol);
  EXPECT_NEAR(whole.inertia.I_SScm_R(2, 2), 0.5, kTol);
  EXPECT_EQ(whole.unreachable_links, (std::vector<int>{2}));
}

// A fixed-joint cycle (malformed input) terminates and still puts every link in one group.
TEST(WeldedGroupsTest, AFixedJointCycleIsCutAndEveryLinkIsInExactlyOneGroup) {
  Model model;
  for (const char* name : {"a", "b", "c"}) model.links.push_back(MakeFrame(name));
  model.joints.push_back(MakeJoint("ab", Joint::Type::kFixed, "a", "b"));
  model.joints.push_back(MakeJoint("bc", Joint::Type::kFixed, "b", "c"));
  model.joints.push_back(MakeJoint("ca", Joint::Type::kFixed, "c", "a"));
  const std::vector<WeldedGroup> groups = FindWeldedGroups(model);
  size_t total = 0;
  for (const WeldedGroup& g : groups) total += g.links.size();
  EXPECT_EQ(total, 3u);
}

}  // namespace
}  // namespace massprops
