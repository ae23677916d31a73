#pragma once
// What the dynamics tests share: small URDF robots written inline and read through the model
// reader into a KinematicTree, and joint vectors from lists.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "massprops/dynamics/kinematic_tree.h"
#include "massprops/io/model_reader.h"

namespace massprops::test_support {

/// The tree of a URDF text (a test failure, and an exception from .at(), when it is none).
inline KinematicTree TreeOf(const std::string& urdf) {
  const ReadResult read = ReadModelString(urdf, "robot.urdf");
  EXPECT_TRUE(read.ok() && read.models.size() == 1) << (read.ok() ? "" : read.errors[0].ToString());
  const KinematicTreeResult made = MakeKinematicTree(read.models.at(0));
  EXPECT_TRUE(made.tree.has_value()) << made.error;
  return made.tree.value();
}

/// An <inertial> at `xyz` with the given mass and <inertia> attributes.
inline std::string InertialXml(const std::string& xyz, double mass, const std::string& moments) {
  return "<inertial><origin xyz='" + xyz + "'/><mass value='" + std::to_string(mass) +
         "'/><inertia " + moments + "/></inertial>";
}

/// A <joint> with the given <origin> attributes and axis (and wide limits, which urdfdom wants).
inline std::string JointXml(const std::string& name, const std::string& type,
                            const std::string& parent, const std::string& child,
                            const std::string& origin, const std::string& axis) {
  return "<joint name='" + name + "' type='" + type + "'><parent link='" + parent +
         "'/><child link='" + child + "'/><origin " + origin + "/><axis xyz='" + axis +
         "'/><limit lower='-9' upper='9' effort='1' velocity='1'/></joint>";
}

inline Eigen::VectorXd V(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double x : values) v(i++) = x;
  return v;
}

}  // namespace massprops::test_support
