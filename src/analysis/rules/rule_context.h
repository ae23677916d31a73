#pragma once
// The machinery the rules of `massprops check` share (private to src/analysis/): the per-model
// context a rule reads (welded groups, the joint tree, the memo of each link's geometry bounds,
// the link judged against its geometry), the way a rule emits a finding (severity overrides,
// rules ignored per link), number formatting and the physical-validity helpers. Each rule is a
// file of src/analysis/rules/ (rules.h lists them); src/analysis/checks.cc runs them in order.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/rules/farthest_point.h"
#include "massprops/analysis/check_stats.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/finding_text.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/model/model.h"

namespace massprops {
namespace rules {

// Collision and visual primitives are often simplified (smaller than the body: a cylinder for the
// motor of a link whose casting reaches farther). The geometry rules therefore allow the body to
// reach kGeometryMargin times the half-diagonal r of the geometry's bounding box: they flag an
// inertia only if its mass cannot fit in the sphere of radius kGeometryMargin·r about the box
// center, and a center of mass only if it is more than (kGeometryMargin − 1)·r outside the box.
constexpr double kGeometryMargin = 2;
// A link whose known geometry includes meshes that were read, and nothing of unknown size: a mesh
// from CAD is the part's envelope, not a simplification, so the body may reach only a little
// beyond its box (exporters' rounding, a part drawn a little smaller than its collision): the
// margin is this instead of kGeometryMargin.
constexpr double kMeshGeometryMargin = 1.1;
// A center of mass outside a whole mesh geometry's box by more than this many half-diagonals is
// flagged (a mirrored part's COM copied from its twin lies a whole box-width away; a few mm out of
// a 4 cm box is an exporter's frame rounding or a screw drawn elsewhere).
constexpr double kMeshComMargin = 0.25;

// Placeholder geometry: a link whose geometry's half-diagonal is below this (a 1 mm sphere, a
// zero-size box) has no size to judge its inertia by. Dummy masses: a link of at most this mass
// (0.1 to 1 g markers, frames given a token mass so that a parser accepts them) is not a body
// whose inertia matters; the geometry rules say nothing about either.
constexpr double kPlaceholderHalfDiagonal = 0.005;  // metres
constexpr double kDummyMass = 1e-3;                 // kg
constexpr double kMarkerHalfDiagonal = 0.01;        // metres: a 1 cm cube is 0.00866
// Where part of a welded group's geometry is a mesh of unknown size, the known geometry may cover
// only part of the body: the geometry rules allow it to reach this many times farther.
// An inertia is judged so (2: the known primitives, each already allowed kGeometryMargin, stand
// for a body at most twice farther: a camera's collision box with its visual mesh unread); a
// center of mass, and anything judged against a 1 cm marker, with kMarkerGeometryMargin.
constexpr double kPartialGeometryMargin = 2;
constexpr double kMarkerGeometryMargin = 3;
// A typed-in inertia on a link with nothing to judge it by matters when it is at least this share
// of its welded group's central inertia (an error of 5% in a body's inertia is about what careful
// identification achieves, so more than that changes what a controller sees).
constexpr double kMadeUpInertiaShare = 0.05;

std::string Format(const char* format, ...) __attribute__((format(printf, 1, 2)));
// A number as %g with 6 significant digits (enough to recognise the file's numbers).
std::string Num(double x);
// "(x, y, z)" with Num.
std::string Vec(const Eigen::Vector3d& v);

// The physical-validity facts of an inertia matrix at a center of mass.
struct Validity {
  bool finite = false;
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();  // ascending principal moments
  double trace = 0;
  double excess = 0;  // λ3 − (λ1 + λ2): positive when the triangle inequality fails
};
Validity Analyze(const Eigen::Matrix3d& I);
bool IsValid(const Eigen::Matrix3d& I, double relative_tolerance);
// "principal moments 0.1, 0.2, 0.5: 0.1 + 0.2 < 0.5 (by 0.2 = 25% of the trace)".
std::string DescribeViolation(const Validity& v);
// The values of a finding about the validity `v` of an inertia judged with `tolerance`.
std::vector<std::pair<std::string, double>> ValidityValues(const Validity& v, double tolerance);

// The inertia matrix as written: about the center of mass, in the inertial frame.
Eigen::Matrix3d WrittenMatrix(const Inertial& in);
// The bounds of a link's collision (or visual) geometry when all of it are known primitives.
std::optional<GeometryBounds> BoundsOf(const Link& link, bool collision);
// Why a link's inertia cannot be judged by its geometry, or "" when it can: placeholder geometry
// (half-diagonal below kPlaceholderHalfDiagonal) or a dummy mass.
std::string UnjudgedBecause(const Link& link, const std::optional<GeometryBounds>& bounds);

// The <inertia> element if present, else the <inertial>, else the <link>.
const SourceLocation& InertiaLocation(const Link& link);
// The <mass> element if present, else InertiaLocation.
const SourceLocation& MassLocation(const Link& link);
// The <origin>/<pose> of the inertial if present, else InertiaLocation.
const SourceLocation& PoseLocation(const Link& link);

// The "too large" verdicts of the geometry rules are made against the group's known geometry;
// where some of it is of unknown size (a mesh not read), the body may reach farther: the
// allowance is then kPartialGeometryMargin times larger.
// For a center of mass, and for an inertia judged against a marker (which says where a link
// is, not how large), kMarkerGeometryMargin: a collision stub around a joint or a frame marker
// may stand for a body that reaches well beyond it.
double Allowance(const GeometryBounds& group_bounds, bool for_inertia);
// How far beyond its geometry's box a body may reach, in half-diagonals: kMeshGeometryMargin
// when the geometry is known whole and includes meshes (a CAD envelope), kGeometryMargin for
// primitives (often simplified).
double MarginOf(const GeometryBounds& bounds);

// A link with a positive mass, and the geometry its inertia and center of mass are judged by.
struct JudgedLink {
  const Link* link = nullptr;
  int index = -1;
  std::string who;            // "link 'name'"
  bool valid = false;         // the written inertia is valid within the tolerance
  Eigen::Matrix3d I_written;  // as written: about the center of mass, in the inertial frame
  MassProperties props;       // about the center of mass, in the link frame
  // The link as a solid of its geometry (primitives; meshes through options.shape).
  std::optional<LinkShape> shape;
  // Its own geometry's extent; none for placeholder geometry and dummy masses.
  std::optional<GeometryBounds> bounds;
  // Why bounds is empty although the link has geometry: "placeholder geometry (...)" or
  // "a dummy mass (...)"; empty otherwise.
  std::string unjudged_because;
  // Too small is judged against the smaller of the collision and the visual geometry when both
  // are known primitives of a real size (either may describe the body): its half-diagonal.
  double smallest_extent = 0;
  // The extent its inertia and center of mass must fit: its own, or its welded group's.
  std::optional<GeometryBounds> group_bounds;
  std::string geometry_name;  // "collision", "visual mesh", ...
  // Its collision geometry is all primitives, and the inertia is judged against its own
  // geometry: the collision is the body's envelope for the simulator (already allowed
  // kGeometryMargin for simplification), whatever its unread visual meshes draw.
  bool collision_envelope = false;
};

// What the rules of one model share: the model and options, its welded groups and joint tree,
// the memo of each link's geometry bounds, and the findings emitted so far.
class RuleContext {
 public:
  RuleContext(const Model& model, const CheckOptions& options);

  const Model& model;
  const CheckOptions& options;
  std::vector<WeldedGroup> groups;
  std::vector<int> group_of;  // link index -> index into groups
  // children[l]: (child link, joint) of every joint from link l that is its child's tree parent
  // joint (the first in file order, as FindWeldedGroups decides).
  std::vector<std::vector<std::pair<int, int>>> children;
  std::vector<int> parent;             // link index -> its tree parent link, or -1
  std::vector<bool> welded_to_world;   // link index -> the child of a fixed joint to the world
  double total_mass = 0;               // the model's mass
  bool sdf_without_inertials = false;  // an SDF model none of whose links has an <inertial>
  bool model_note_given = false;       // model-without-inertials said
  std::vector<Finding> findings;
  // The expensive measurements taken (CheckModel's stats; the memos of const questions count too).
  mutable CheckStats stats;

  // Whether `rule` is on in this run (its severity after the overrides): a rule that is off
  // is not computed (Emit would drop every finding of it anyway).
  bool RuleOn(const std::string& rule) const { return SeverityOf(rule).has_value(); }

  // The welded group of link `link_index`.
  const WeldedGroup& GroupOf(int link_index) const { return groups[group_of[link_index]]; }

  // Adds a finding of `rule` on `link` unless the rule is off or the link ignores it; returns
  // it (for the rule to set its headline, evidence and help), or nullptr when it was not added.
  Finding* Emit(const std::string& rule, const Link& link, const SourceLocation& location,
                std::string message, std::vector<std::pair<std::string, double>> values);
  // Emit, and the finding's headline, evidence and help (checks.h; numbers written with
  // finding_text.h). A headline that starts "link 'NAME'" and is longer than kMaxHeadlineChars
  // is rewritten as LinkHeadline(NAME, rest) writes it.
  void Emit(const std::string& rule, const Link& link, const SourceLocation& location,
            std::string message, std::vector<std::pair<std::string, double>> values,
            std::string headline, std::vector<std::pair<std::string, double>> evidence,
            std::string help);

  // The composite of link `child_link` and everything outboard of it (its welded group and every
  // group attached below, through any joint, at the zero configuration), about and expressed in
  // `child_link`'s frame; nullopt when a member's <inertial> could not be read. The first call
  // composes every link's subtree once, leaves first (each from its own part and its children's
  // composites), so that asking for every link of a chain costs the chain, not its square.
  std::optional<CompositeInertia> OutboardComposite(int child_link) const;

  // The known extent of link `link_index`'s geometry (primitives, and mesh boxes through
  // options.box), computed once per link: a link is looked at by each member of its group.
  const std::optional<GeometryBounds>& BoundsOfLink(int link_index) const;

  // The mass properties of link `link_index` (of positive mass) and the geometry they are
  // judged by.
  JudgedLink JudgeAgainstGeometry(int link_index, const std::string& who, bool valid) const;

  // The pose of link `link_index` in the frame of its welded group's root.
  const Pose& GroupPoseOf(int link_index) const {
    return groups[group_of[link_index]].X_RL[index_in_group_[link_index]];
  }

  // The composite of welded group `group_index` (CalcCompositeInertia), computed once per group:
  // each member asks for its group's (a per-link question over the group would make a welded
  // group of n links cost n^2).
  const CompositeInertia& GroupComposite(int group_index) const;

  // Whether welded group `group_index` holds a link fixed to a parent outside the model (the
  // world): welded_to_world of any member, answered once per group.
  bool GroupWeldedToWorld(int group_index) const { return group_welded_to_world_[group_index]; }

  // The known geometry of a welded group, as its members' box corners in the root's frame R
  // (an index for the farthest of them from a point), and whether some member's geometry is of
  // unknown or partly unknown size: built once per group, for every member that asks how far the
  // group reaches from it.
  struct GroupCorners {
    FarthestPointIndex corners_R{{}};
    bool partial = false;
  };
  const GroupCorners& GroupCornersOf(int group_index) const;

  // How many members of `group` contribute mass or inertia (SDF gives a link without <inertial>
  // mass 1); sets *all_massless to false when some member has a mass.
  int CountContributingMembers(const WeldedGroup& group, bool* all_massless) const;

  // For an invalid member of a welded group: whether the group is valid as a whole.
  std::string GroupNote(int link_index) const;

  // Whether every joint to a child of link `link_index` lies within kGeometryMargin of `bounds`.
  bool JointsWithin(int link_index, const GeometryBounds& bounds) const;

 private:
  void BuildJointTree();
  // The severity of `rule` after the overrides, or nullopt when the rule is off.
  std::optional<Severity> SeverityOf(const std::string& rule) const;
  bool Enabled(const std::string& rule, const Link& link) const;
  // The union of the known geometry of every link of `link_index`'s welded group, in that link's
  // frame, starting from the link's own `bounds`.
  std::optional<GeometryBounds> GroupBounds(int link_index, const GeometryBounds& bounds) const;

  mutable std::vector<std::optional<std::optional<GeometryBounds>>> bounds_of_link_;
  std::vector<int> index_in_group_;  // link index -> its place in its group's links and X_RL
  std::vector<bool> group_welded_to_world_;
  mutable std::vector<std::optional<GroupCorners>> corners_of_group_;
  mutable std::vector<std::optional<CompositeInertia>> composite_of_group_;
  void ComposeSubtrees() const;
  mutable std::vector<std::optional<CompositeInertia>> subtree_;  // OutboardComposite's
  mutable bool subtrees_composed_ = false;
};

}  // namespace rules
}  // namespace massprops
