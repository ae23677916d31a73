#pragma once
// The bridge of the MuJoCo tests of the dynamics (tests/inverse_dynamics_mujoco_test.cc,
// tests/identify_mujoco_test.cc): a URDF without its geometry (whose meshes are not all in the
// corpus) for libmujoco to load; the libmujoco model of the same URDF mapped to a KinematicTree
// joint by joint and body by body, and its bodies' mass properties set from a tree's parameters.
// Why each setting (tests/inverse_dynamics_mujoco_test.cc, top): MuJoCo's own compile
// diagonalizes inertias with mju_eig3, which stops at about 1e-6 rad, so the bodies are set from
// the tree's parameters diagonalized by Eigen to round-off (and body_sameframe cleared, so that
// MuJoCo uses the inertial frame set).

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>
#include <tinyxml2.h>
#include <unistd.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "massprops/dynamics/kinematic_tree.h"

namespace massprops::test_support {

// The URDF without <visual> and <collision>, written to a temporary file; its path.
inline std::string WithoutGeometry(const std::string& path, const std::string& name) {
  tinyxml2::XMLDocument doc;
  EXPECT_EQ(doc.LoadFile(path.c_str()), tinyxml2::XML_SUCCESS) << path;
  tinyxml2::XMLElement* robot = doc.RootElement();
  for (tinyxml2::XMLElement* link = robot->FirstChildElement("link"); link;
       link = link->NextSiblingElement("link")) {
    for (const char* tag : {"visual", "collision"}) {
      while (tinyxml2::XMLElement* e = link->FirstChildElement(tag)) link->DeleteChild(e);
    }
  }
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("massprops_id_mujoco_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string out = (dir / name).string();
  EXPECT_EQ(doc.SaveFile(out.c_str()), tinyxml2::XML_SUCCESS);
  return out;
}

struct Loaded {
  mjModel* m = nullptr;
  std::vector<int> dof, qpos, body;  // per joint of the tree
};

// Maps the tree's joints and bodies to MuJoCo's; checks MuJoCo's compiled mass properties.
inline Loaded MapToMujoco(mjModel* m, const KinematicTree& tree) {
  Loaded out;
  out.m = m;
  EXPECT_EQ(m->nv, tree.size()) << "MuJoCo has other joints than the tree";
  for (const MovingBody& b : tree.bodies) {
    const int joint = mj_name2id(m, mjOBJ_JOINT, b.joint.c_str());
    const int body = mj_name2id(m, mjOBJ_BODY, b.link.c_str());
    EXPECT_GE(joint, 0) << b.joint;
    EXPECT_GE(body, 0) << b.link;
    if (joint < 0 || body < 0) return out;
    EXPECT_EQ(m->jnt_bodyid[joint], body);
    out.dof.push_back(m->jnt_dofadr[joint]);
    out.qpos.push_back(m->jnt_qposadr[joint]);
    out.body.push_back(body);
    const double mass = b.pi_BBo_B(0);
    const Eigen::Vector3d c = b.pi_BBo_B.segment<3>(1) / mass;
    EXPECT_NEAR(m->body_mass[body], mass, 1e-9 * mass) << b.link;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(m->body_ipos[3 * body + k], c(k), 1e-9) << b.link;
  }
  EXPECT_EQ(static_cast<int>(out.body.size()) + 1, m->nbody) << "bodies besides the tree's";
  return out;
}

// Sets MuJoCo's mass properties of each body from the tree's parameters, diagonalized to
// round-off; checks MuJoCo's own principal moments first (to mju_eig3's accuracy).
// check_principal: MuJoCo's compiled principal moments must first equal the tree's (to mju_eig3's
// accuracy), i.e. MuJoCo read the same bodies; off to set other bodies (a "true" arm).
inline void SetInertias(const Loaded& loaded, const KinematicTree& tree,
                        bool check_principal = true) {
  mjModel* m = loaded.m;
  for (std::size_t i = 0; i < tree.bodies.size(); ++i) {
    const InertialParameters& p = tree.bodies[i].pi_BBo_B;
    const int body = loaded.body[i];
    const double mass = p(0);
    const Eigen::Vector3d c = p.segment<3>(1) / mass;
    Eigen::Matrix3d I_O;
    I_O << p(4), p(5), p(7), p(5), p(6), p(8), p(7), p(8), p(9);
    const Eigen::Matrix3d I_c =
        I_O - mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(I_c);
    Eigen::Matrix3d R = eig.eigenvectors();
    if (R.determinant() < 0) R.col(2) *= -1;
    const Eigen::Quaterniond quat(R);
    const double scale = eig.eigenvalues().maxCoeff();
    Eigen::Vector3d mujoco(m->body_inertia[3 * body], m->body_inertia[3 * body + 1],
                           m->body_inertia[3 * body + 2]);
    std::sort(mujoco.data(), mujoco.data() + 3);
    if (check_principal) {
      EXPECT_LT((mujoco - eig.eigenvalues()).norm(), 1e-5 * scale) << tree.bodies[i].link;
    }
    m->body_mass[body] = mass;
    for (int k = 0; k < 3; ++k) {
      m->body_ipos[3 * body + k] = c(k);
      m->body_inertia[3 * body + k] = eig.eigenvalues()(k);
    }
    const double q[4] = {quat.w(), quat.x(), quat.y(), quat.z()};
    for (int k = 0; k < 4; ++k) m->body_iquat[4 * body + k] = q[k];
    // MuJoCo's compiler marks a body whose inertial frame it found equal to the body frame
    // (body_sameframe, mjmodel.h), and its kinematics then skip body_iquat and body_ipos for
    // it. The frame set here is another (a diagonal inertia of ixx = iyy > izz, as the UR arms'
    // shoulders have, is ordered ascending, so its iquat turns x onto z): left set, MuJoCo
    // computed that body's inertia about the wrong axes, 5.8e-3 of the UR5's largest torque.
    m->body_sameframe[body] = 0;
  }
}

}  // namespace massprops::test_support
