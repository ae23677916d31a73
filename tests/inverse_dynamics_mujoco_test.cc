// Inverse dynamics (massprops/dynamics/inverse_dynamics.h) against libmujoco's mj_inverse
// (MuJoCo 2.2.2, Debian libmujoco-dev) at random states of corpus arms and a humanoid on a fixed
// pelvis: the joint torques must agree to 1e-9 of the sample's largest torque. Built only when
// libmujoco is installed (tests/CMakeLists.txt).
//
// MuJoCo loads the same URDF (a copy without <visual> and <collision>, whose meshes are not all
// in the corpus; every link compared has an <inertial>, so MuJoCo takes no mass from geoms). Its
// URDF defaults fuse the links of fixed joints into the body they ride on (fusestatic), as
// MakeKinematicTree welds them. So that both compute the same dynamics:
//   - constraints (joint limits, friction loss) and passive forces (damping, springs) are
//     disabled, armature is set to 0: mj_inverse then returns M(q)·q̈ + c(q, q̇) alone
//     (qfrc_inverse = M·qacc + qfrc_bias − qfrc_passive − qfrc_constraint);
//   - gravity is the tree's, (0, 0, −9.81);
//   - each body's mass, center of mass and principal inertia are set from the tree's parameters,
//     diagonalized by Eigen's SelfAdjointEigenSolver: MuJoCo's own compile diagonalizes with
//     mju_eig3, which stops at about 1e-6 rad (tests/mjcf_reader_mujoco_test.cc), far above the
//     1e-9 compared here. MuJoCo's compiled mass and center of mass are first checked equal to the
//     tree's to 1e-9, and its principal moments to 1e-5 (that the bodies are the same).
// A second pass turns MuJoCo's damping and armature on and sets the tree's viscous friction and
// armature to the same numbers.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>
#include <tinyxml2.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "massprops/dynamics/inverse_dynamics.h"
#include "massprops/io/model_reader.h"
#include "mujoco_dynamics_support.h"
#include "shared_data.h"

namespace massprops {
namespace {

namespace fs = std::filesystem;
using test_support::Loaded;
using test_support::MapToMujoco;
using test_support::SetInertias;
using test_support::WithoutGeometry;

// Measured (2026-12-02): every arm agrees to about 1e-15 of the largest torque. The UR5 and UR10
// disagreed by 5.8e-3 / 4.0e-3 and the Panda by 7.2e-6 until SetInertias cleared MuJoCo's
// body_sameframe (mujoco_dynamics_support.h): MuJoCo then ignored the inertial frame set for
// the bodies it had compiled with an identity one (the UR shoulders' M(0,0) was off by exactly
// ixx - izz = 0.0102675 - 0.00666 kg·m², the file's numbers).
const char* const kRobots[] = {
    "drake-models/iiwa_description/urdf/iiwa14_no_collision.urdf",
    "unitree_ros/robots/h1_description/urdf/h1.urdf",
    "example-robot-data/robots/panda_description/urdf/panda.urdf",
    "example-robot-data/robots/ur_description/urdf/ur5_robot.urdf",
    "example-robot-data/robots/ur_description/urdf/ur10_robot.urdf",
};

// The largest |τ_ours − τ_mujoco| / |τ_mujoco|∞ over random states.
double WorstRelativeDifference(const Loaded& loaded, const KinematicTree& tree,
                               std::mt19937_64& rng) {
  mjData* d = mj_makeData(loaded.m);
  std::uniform_real_distribution<double> any(-2, 2);
  double worst = 0;
  const int n = tree.size();
  for (int sample = 0; sample < 100; ++sample) {
    Eigen::VectorXd q(n), dq(n), ddq(n);
    for (int i = 0; i < n; ++i) {
      q(i) = any(rng);
      dq(i) = any(rng);
      ddq(i) = 3 * any(rng);
      d->qpos[loaded.qpos[static_cast<std::size_t>(i)]] = q(i);
      d->qvel[loaded.dof[static_cast<std::size_t>(i)]] = dq(i);
      d->qacc[loaded.dof[static_cast<std::size_t>(i)]] = ddq(i);
    }
    mj_inverse(loaded.m, d);
    const Eigen::VectorXd ours = CalcInverseDynamics(tree, q, dq, ddq);
    Eigen::VectorXd theirs(n);
    for (int i = 0; i < n; ++i)
      theirs(i) = d->qfrc_inverse[loaded.dof[static_cast<std::size_t>(i)]];
    worst = std::max(worst,
                     (ours - theirs).lpNorm<Eigen::Infinity>() / theirs.lpNorm<Eigen::Infinity>());
  }
  mj_deleteData(d);
  return worst;
}

TEST(InverseDynamicsMujocoTest, TorquesEqualMjInverseOnCorpusArmsAndAHumanoid) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus");
  std::mt19937_64 rng(21);
  for (const char* file : kRobots) {
    SCOPED_TRACE(file);
    const std::string path = test_support::SharedDir() + "/corpus/" + file;
    const ReadResult read = ReadModelFile(path);
    ASSERT_TRUE(read.ok());
    const KinematicTreeResult made = MakeKinematicTree(read.models.at(0));
    ASSERT_TRUE(made.tree.has_value()) << made.error;
    KinematicTree tree = *made.tree;
    const std::string copy = WithoutGeometry(path, fs::path(file).filename().string());
    char error[1000] = "";
    mjModel* m = mj_loadXML(copy.c_str(), nullptr, error, sizeof error);
    ASSERT_NE(m, nullptr) << error;
    const Loaded loaded = MapToMujoco(m, tree);
    ASSERT_EQ(static_cast<int>(loaded.dof.size()), tree.size());
    SetInertias(loaded, tree);
    for (int i = 0; i < 3; ++i) m->opt.gravity[i] = tree.gravity_base(i);
    m->opt.disableflags |= mjDSBL_CONSTRAINT | mjDSBL_PASSIVE;
    for (int v = 0; v < m->nv; ++v) m->dof_armature[v] = 0;
    const double rigid = WorstRelativeDifference(loaded, tree, rng);
    EXPECT_LT(rigid, 1e-9);
    // Damping (MuJoCo's passive −b·q̇) and armature against the tree's viscous friction and
    // armature.
    m->opt.disableflags &= ~mjDSBL_PASSIVE;
    std::uniform_real_distribution<double> unit(0, 1);
    for (std::size_t i = 0; i < tree.bodies.size(); ++i) {
      tree.friction[i] = JointFriction{unit(rng), 0, 0, unit(rng)};
      m->dof_damping[loaded.dof[i]] = tree.friction[i].viscous;
      m->dof_armature[loaded.dof[i]] = tree.friction[i].armature;
    }
    for (int j = 0; j < m->njnt; ++j) m->jnt_stiffness[j] = 0;
    const double damped = WorstRelativeDifference(loaded, tree, rng);
    EXPECT_LT(damped, 1e-9);
    std::cout << file << ": " << tree.size() << " joints, worst |Δτ|/|τ|∞ " << rigid << " (rigid), "
              << damped << " (damping, armature)\n";
    mj_deleteModel(m);
  }
}

}  // namespace
}  // namespace massprops
