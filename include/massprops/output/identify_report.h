#pragma once
/// @file
/// The report of `massprops identify` (docs/identify.md) as data: each body's mass, center of
/// mass and principal moments from its 10 inertial parameters, and the JSON document of
/// `--format json`, shared by the tool and Python's massprops.identify.

#include <Eigen/Core>
#include <string>

#include "massprops/analysis/identify.h"

namespace massprops {

/// A body's mass properties from its parameters π (kinematic_tree.h): mass, center of mass and
/// central inertia in the body frame, principal moments (ascending). All zero but the mass when
/// the mass is not positive or π is not finite. Never throws.
struct BodyCentralProperties {
  double mass = 0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  Eigen::Matrix3d I_BBcm_B = Eigen::Matrix3d::Zero();
  Eigen::Vector3d principal = Eigen::Vector3d::Zero();
};
BodyCentralProperties CentralPropertiesOf(const InertialParameters& pi);

/// {"identifiability": {"rank", "parameters", "condition_number" (null when infinite),
/// "unexcited_links", "base_parameters": [{"name", "file", "least_squares", "identified",
/// "standard_error"}]}, "training_samples", "validation_samples", "joints": [{"joint",
/// "rms_file", "rms_least_squares", "rms_identified"}], "links": [{"link", "file" and
/// "identified" (each {"mass", "com", "principal_moments", "parameters"}; the identified one
/// also "mass_standard_error", "com_standard_error", "principal_moments_standard_error"),
/// "least_squares_consistent", "identified_consistent", "geometry_bound", "ellipsoid_ratio"
/// ({"file", "least_squares", "identified"}, null where not imposed) and
/// "least_squares_within_geometry" (null where not imposed)}], "inconsistent_least_squares_links",
/// "geometry_bound_links", "least_squares_outside_geometry_links", "solver": {"status",
/// "iterations"}}, indented by two spaces, ending in a newline. `r` must be
/// Identify(tree, ...). Never throws.
std::string RenderIdentifyJson(const KinematicTree& tree, const IdentifyResult& r);

}  // namespace massprops
