#pragma once
/// @file
/// `massprops merge-fixed`: a model in which every welded group (links joined by fixed joints) is
/// one link carrying the composite inertial, as simulators that lump fixed joints do. For URDF the
/// original document is edited (tinyxml2), so every other element of the file is kept: the merged
/// child links and the fixed joints that held them are removed, their <visual>s and <collision>s
/// move into the group's root link with composed origins, joints whose parent was a merged link
/// are re-parented to the root link with composed origins, and the root link's <inertial> becomes
/// the group's composite (center of mass as origin, rpy 0, inertia about it in the root frame,
/// numbers written with max_digits10 so they read back exactly). For SDF the same is done per
/// top-level <model> with SDF's pose semantics (details at MergeFixedJoints).

#include <string>
#include <vector>

#include "massprops/analysis/target_profile.h"
#include "massprops/model/model.h"

namespace massprops {

/// What MergeFixedJoints returns.
struct MergeFixedResult {
  std::string text;                ///< The merged model (empty when errors is not empty).
  std::vector<ReadError> errors;   ///< Read errors of the input, or "not supported".
  int merged_links = 0;            ///< Links folded into their group's root link.
  int groups_merged = 0;           ///< Welded groups of more than one link.
  std::vector<std::string> notes;  ///< What the user should know (e.g. nothing was merged, why).
};

/// Merges the welded groups of the model text `xml` (`file_name` names it in errors), URDF or SDF.
/// SDF: in every top-level <model> written in the file, each group's root link gets the composite
/// <inertial> (<pose> = center of mass, no rotation; <inertia> about it in the link frame; numbers
/// the shortest decimals that read back exactly); the members' <visual>, <collision>, <sensor>,
/// <light>, <projector>, <particle_emitter>, <audio_source>, <audio_sink> and <battery> move into
/// it with composed poses (renamed "LINK__NAME" when the root already has one of that name); the
/// members and the fixed joints between them are removed; joints, <frame attached_to> and poses
/// (relative_to), axes (expressed_in) and canonical_link that named a member are re-pointed to the
/// root with composed poses. A group with a member in a nested <model> or an <include>, a
/// reference to a member from outside its model, a placement_frame naming a member, a moving joint
/// inside a group or a member whose inertial cannot be read is a "merge-fixed does not support
/// this" error at that element (nothing is written). A file without any fixed
/// joint between links comes back re-printed with no change of content. Elements that name a
/// removed link elsewhere (<gazebo reference>, <transmission>) are kept as written. A group's
/// root link keeps its inertial as written when no other member has a mass or an inertia (a
/// massless member's inertia is added, as libsdformat's lumping adds it).
///
/// `target` says which fixed joints are merged: kGeneric every one; kGazebo those Gazebo lumps
/// (GazeboLumpedGroups: a joint named by <gazebo reference="JOINT"> with
/// <disableFixedJointLumping>true or <preserveFixedJoint>true, and a joint from a root link named
/// "world", stay as written, with their <gazebo> elements). kMujoco and kDrake give an error
/// ("not supported": MuJoCo's fusestatic also fuses into the world and drops massless bodies,
/// which a URDF cannot say; Drake keeps every link). SDF with kGazebo: gz-sim does not lump the
/// fixed joints of SDF models, so the text comes back unchanged, with a note saying so.
/// Never throws for bad input. Cost: linear in the size of the file.
MergeFixedResult MergeFixedJoints(const std::string& xml, const std::string& file_name,
                                  Target target = Target::kGeneric);

/// URDF roll-pitch-yaw angles (R = Rz(yaw)·Ry(pitch)·Rx(roll)) of the rotation R; near pitch
/// ±90° yaw is set to 0. Precondition: R is a rotation matrix (not checked).
Eigen::Vector3d RotationToRollPitchYaw(const Eigen::Matrix3d& R);

}  // namespace massprops
