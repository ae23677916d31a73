#pragma once
/// @file
/// Repairs behind `massprops fix`: for a link whose findings have a known remedy, the new
/// <inertial> numbers, which attributes (or SDF element texts) of which element change, and why.
/// The math lives here; rewriting the file is xml_patch.h's job.
///
/// The numbers of a repaired inertial are always written in the link's existing inertial frame
/// Bi (URDF <inertial><origin rpy>, SDF <inertial><pose>): an inertia computed in the link frame B
/// is re-expressed as R_BBiᵀ·I_B·R_BBi before it is written.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "massprops/analysis/link_shape.h"
#include "massprops/model/model.h"

namespace massprops {

struct Finding;

/// How `inertia-not-physical` is repaired.
enum class InertiaRepairMethod {
  /// The nearest valid inertia in the Frobenius norm: the principal moments λ are projected onto
  /// the set where Σ = ½·tr(I)·1 − I is positive semi-definite with a small positive floor
  /// (σ_i >= kValidityFloor·max|λ|), keeping the principal axes.
  kProject,
  /// MuJoCo's `balanceinertia`: all three principal moments are set to their mean (when the mean
  /// is not positive, to the mean of their absolute values), which is always valid.
  kBalance,
};

/// The floor of the projection, relative to the largest |principal moment| of the input: the
/// repaired inertia is valid by a margin far above round-off (32·eps) and far below any tolerance
/// a check uses (1e-6), so it is strictly valid once written with round-trip digits.
inline constexpr double kValidityFloor = 1e-9;

/// The density used for a link's mass when it has to come from its geometry (water, kg/m³).
inline constexpr double kDefaultDensity = 1000;

/// The rules whose repairs are guesses (heuristics): planned only when named in
/// RepairOptions::apply (`massprops fix --apply RULE,...`). Every other repair answers an error
/// that physics decides (`inertia-not-physical`: the nearest valid inertia) and is planned by
/// default. `mass-not-positive`, `massless-moving-body` and `inertial-missing` are repaired from
/// the geometry and a density, a guess too.
const std::vector<std::string>& HeuristicRepairRules();

struct RepairOptions {
  InertiaRepairMethod method = InertiaRepairMethod::kProject;
  /// The heuristic repairs asked for, by rule id (see HeuristicRepairRules; "all" means every
  /// one). Empty (the default): only repairs of error findings that physics decides.
  std::vector<std::string> apply;
  /// Repair `units-suspect` even when more than one unit mistake would explain the numbers (then
  /// the one whose radius of gyration lands nearest half the geometry's half-diagonal is taken).
  /// Implies apply "units-suspect".
  bool fix_units = false;
  double density = kDefaultDensity;  ///< kg/m³, for masses computed from geometry. > 0.
  /// --from-geometry: replace the inertial of every link with usable geometry (primitives, or
  /// meshes through `shape`) ...
  bool from_geometry_all = false;
  /// ... or of these links only.
  std::vector<std::string> from_geometry_links;
  /// Validity tolerance (as CheckOptions::tolerance): valid inputs are returned unchanged.
  double tolerance = 1e-6;
  /// The shape of links whose geometry is not all primitives (meshes): used where primitives
  /// are (from-geometry, units, products sign) when set; see CheckOptions::shape. `massprops fix`
  /// sets MakeLinkShapeFunction with --geometry or --from-geometry.
  LinkShapeFunction shape;
  /// The bounding box of links with meshes (CheckOptions::box): the extent the units repair and
  /// the re-check of every repair judge by, as `check` does. `massprops fix` sets
  /// MakeLinkBoxFunction unless --no-geometry.
  LinkBoxFunction box;
  /// As CheckOptions::points (the re-check of each repair uses it).
  LinkPointsFunction points;
};

/// One number (or a run of numbers) of the file that a repair changes.
struct FieldChange {
  std::string element;  ///< "mass", "inertia", "origin" (URDF) or "pose" (SDF).
  /// URDF: the attribute ("value", "ixx", "xyz"). SDF: the child element of <inertia> whose text
  /// changes ("ixx", ...), or "" for the text of `element` itself (<mass>, <pose>).
  std::string attribute;
  int line = 0;  ///< Line of `element`'s start tag in the original text (0: inserted).
  /// The element's value is a list of numbers separated by white space; the numbers at
  /// first_token, first_token + 1, ... are replaced by new_values (the others are kept as written).
  int first_token = 0;
  std::vector<double> old_values;
  std::vector<double> new_values;
};

/// The new mass properties of one link, and how they differ from the file.
struct Repair {
  std::string rule;    ///< The finding it answers first, e.g. "inertia-not-physical".
  std::string link;    ///< The link's name.
  std::string method;  ///< "project", "balance", "negate-products", "rescale-units",
                       ///< "shift-to-com", "from-geometry", "from-geometry-density".
  /// The inertial as written; absent for `inertial-missing`.
  std::optional<Inertial> before;
  /// The repaired inertial: mass, X_BBi (rotation unchanged), six numbers in Bi.
  Inertial after;
  /// True when a new <inertial> element is inserted into the link (`inertial-missing`).
  bool inserts_inertial = false;
  /// True when an <origin>/<pose> element is inserted into an existing <inertial> (the center
  /// of mass moves and the file has none).
  bool inserts_origin = false;
  /// The numbers that change, with their element and line (empty when inserts_inertial).
  std::vector<FieldChange> changes;
  int link_line = 0;  ///< Line of the <link> start tag (where an inserted <inertial> goes).
  std::string why;    ///< One or two sentences: what was wrong and what the new numbers are.
  /// ‖I_after − I_before‖_F / ‖I_before‖_F of the inertia matrices in the link frame (for a mass
  /// change with an unchanged inertia: |Δm| / |m|); 1 when there was nothing before.
  double relative_change = 0;
  /// The rules this repair resolves on its link (checked by re-running the checks).
  std::vector<std::string> resolves;
  /// The rules of its link this repair answers: each must be gone after it, or it is refused.
  std::vector<std::string> answers;
};

/// A repair that was planned but is not written, and why: it would leave the finding it answers
/// or create a finding on its link (the repaired model is checked again), or no candidate fits.
struct RefusedRepair {
  std::string rule;  ///< The finding it answered, e.g. "units-suspect".
  std::string link;
  int link_line = 0;
  /// What is wrong with the repair and what a human should look at, e.g. "inertia 1e-20 kg·m² on
  /// a 2.2 kg body: radius of gyration 1e-10 m; ... not repaired".
  std::string why;
  /// The same at a glance, for a headline after "link 'NAME': not repaired: " (fix_text.h): "its
  /// nearest valid inertia does not fit its box either".
  std::string reason;
  /// The numbers that decided, each a whole line of at most kMaxDetailChars − 14 characters
  /// (finding_text.h), in a robot engineer's words.
  std::vector<std::string> evidence;
  /// The repair that was refused (its `after` is what it would have written), when one was
  /// computed; absent when no candidate was found.
  std::optional<Repair> repair;
};

/// The inertia of the link's primitive geometry (box, cylinder, sphere, capsule, ellipsoid):
/// its collisions when it has any, else its visuals; each solid of uniform density, overlaps
/// counted twice. `mass` > 0 scales the result to that mass; otherwise mass = density·volume.
/// Returns the mass properties in the link frame B, or nullopt when the chosen geometries are
/// not all primitives, there are none, or the volume is zero or not finite. Never throws.
struct PrimitiveMassProperties {
  double mass = 0;
  double volume = 0;
  Eigen::Vector3d p_BoBcm_B = Eigen::Vector3d::Zero();
  Eigen::Matrix3d I_BBcm_B = Eigen::Matrix3d::Zero();
  bool from_collision = true;
};
std::optional<PrimitiveMassProperties> CalcPrimitiveMassProperties(const Link& link, double density,
                                                                   double mass = 0);

/// The nearest valid inertia to I (symmetric, finite; products negated as in URDF), by `method`.
/// A valid I (at `tolerance` relative to the trace) is returned unchanged. Never throws; a
/// non-finite I is returned unchanged. Cost: one 3x3 eigen-decomposition, about 1 µs.
Eigen::Matrix3d RepairInertia(const Eigen::Matrix3d& I, InertiaRepairMethod method,
                              double tolerance = 1e-6);

/// The repairs for the findings of `model` (from CheckModel with the same tolerance), one per
/// link, in file order. A link gets a repair when one of its findings has a remedy (see
/// docs/fix.md) or it is named by --from-geometry. Each repair's `resolves` lists the findings of
/// its link that are gone after it (the checks are run again on the repaired model).
/// Every repair is checked again on its own: one that would leave a finding it answers or create
/// a finding the model did not have is dropped and listed in `refused` (when given) with the
/// reason. The numbers of an accepted repair are rounded to the fewest significant digits (at
/// least 6) whose rounded inertial passes the same checks.
/// Never throws for a model the readers produced.
std::vector<Repair> PlanRepairs(const Model& model, const std::vector<Finding>& findings,
                                const RepairOptions& options = {},
                                std::vector<RefusedRepair>* refused = nullptr);

/// Fills repair->changes, inserts_origin and relative_change from `link`'s inertial (the file's
/// numbers) and repair->after, as the planner does for its own repairs.
void FillRepairChanges(const Model& model, const Link& link, Repair* repair);

/// Sets `repair` of every finding that a planned repair resolves (same link, rule in `resolves`).
void AttachRepairs(const std::vector<Repair>& repairs, std::vector<Finding>& findings);

/// The model with the repairs' `after` inertials in place of the links' inertials.
Model ApplyRepairs(const Model& model, const std::vector<Repair>& repairs);

/// "link 'arm' [inertia-not-physical → project]: ixx 0.1 → 0.1, ... (relative change 0.12): why".
std::string DescribeRepair(const Repair& repair);

}  // namespace massprops
