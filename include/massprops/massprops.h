#pragma once
/// @file
/// Everything of the massprops library in one include. The parts, from the bottom up
/// (docs/architecture.md): core (inertia classes and solvers), model (what a reader produces),
/// mesh (triangle meshes), io (readers), dynamics (inverse dynamics and its regressor),
/// analysis (welded groups, checks, repairs, targets, report numbers), output (renderings, the
/// patcher, merge-fixed). Include a part's header directly to depend on less.

// core
#include "massprops/core/eigen_types.h"
#include "massprops/core/format_number.h"
#include "massprops/core/principal_axes.h"
#include "massprops/core/rotational_inertia.h"
#include "massprops/core/spatial_inertia.h"
#include "massprops/core/unit_inertia.h"

// model
#include "massprops/model/model.h"
#include "massprops/model/source_place.h"

// mesh
#include "massprops/mesh/mesh_inertia.h"
#include "massprops/mesh/mesh_loader.h"
#include "massprops/mesh/repository_packages.h"

// io
#include "massprops/io/auto_inertia.h"
#include "massprops/io/mjcf_reader.h"
#include "massprops/io/model_reader.h"
#include "massprops/io/sdf_reader.h"
#include "massprops/io/trajectory_csv.h"
#include "massprops/io/trajectory_rosbag.h"
#include "massprops/io/urdf_reader.h"
#include "massprops/io/xacro_trace.h"

// dynamics
#include "massprops/dynamics/inverse_dynamics.h"
#include "massprops/dynamics/kinematic_tree.h"
#include "massprops/dynamics/torque_regressor.h"

// analysis
#include "massprops/analysis/checks.h"
#include "massprops/analysis/config.h"
#include "massprops/analysis/density_rules.h"
#include "massprops/analysis/finding_sources.h"
#include "massprops/analysis/fix_effect.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/analysis/identifiability.h"
#include "massprops/analysis/identify.h"
#include "massprops/analysis/link_measure.h"
#include "massprops/analysis/link_shape.h"
#include "massprops/analysis/mass_repair.h"
#include "massprops/analysis/mass_report.h"
#include "massprops/analysis/materials.h"
#include "massprops/analysis/model_diff.h"
#include "massprops/analysis/repair.h"
#include "massprops/analysis/target_profile.h"
#include "massprops/analysis/welded_groups.h"

// output
#include "massprops/output/fix_report.h"
#include "massprops/output/merge_fixed.h"
#include "massprops/output/report_format.h"
#include "massprops/output/reporters.h"
#include "massprops/output/xml_patch.h"
