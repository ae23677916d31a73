#include "massprops/analysis/checks.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "massprops/analysis/density_rules.h"
#include "massprops/analysis/geometry_checks.h"
#include "massprops/analysis/target_profile.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/core/principal_axes.h"
#include "massprops/core/rotational_inertia.h"

namespace massprops {
namespace {

// Rule ids (stable; documented in docs/rules.md).
constexpr const char* kMassNotPositive = "mass-not-positive";
constexpr const char* kInertiaNotFinite = "inertia-not-finite";
constexpr const char* kInertiaNotPhysical = "inertia-not-physical";
constexpr const char* kMasslessMovingBody = "massless-moving-body";
constexpr const char* kMasslessWithMassOutboard = "massless-link-with-mass-outboard";
constexpr const char* kZeroInertiaAboutJointAxis = "zero-inertia-about-joint-axis";
constexpr const char* kInertialMissing = "inertial-missing";
constexpr const char* kModelWithoutInertials = "model-without-inertials";
constexpr const char* kProductsSignSuspect = "products-sign-suspect";
constexpr const char* kUnitsSuspect = "units-suspect";
constexpr const char* kInertiaAboutOriginSuspect = "inertia-about-origin-suspect";
constexpr const char* kInertiaExceedsGeometry = "inertia-exceeds-geometry";
constexpr const char* kComOutsideGeometry = "com-outside-geometry";
constexpr const char* kInertiaNearBoundary = "inertia-near-boundary";
// Rules whose findings the readers make (ReadResult::findings).
constexpr const char* kUrdfNotLoadable = "urdf-not-loadable";
constexpr const char* kInertialUnreadable = "inertial-unreadable";
constexpr const char* kIncludeUnresolved = "include-unresolved";

// units-suspect: the radius of gyration k = sqrt(tr(I)/(2m)) is flagged when k / (half-diagonal
// of the geometry's bounding box) is above kUnitsRatio or below 1/kUnitsRatio (a kg·mm² inertia
// makes k sqrt(1e6) = 1000 times too large, a mass in grams makes it sqrt(1000) = 31.6 times too
// small), or, without known geometry, when k exceeds kMaxGyrationRadiusWithoutGeometry.
constexpr double kUnitsRatio = 30;
constexpr double kMaxGyrationRadiusWithoutGeometry = 10;  // metres

// Collision and visual primitives are often simplified (smaller than the body: a cylinder for the
// motor of a link whose casting reaches farther). The geometry rules therefore allow the body to
// reach kGeometryMargin times the half-diagonal r of the geometry's bounding box: they flag an
// inertia only if its mass cannot fit in the sphere of radius kGeometryMargin·r about the box
// center, and a center of mass only if it is more than (kGeometryMargin − 1)·r outside the box.
constexpr double kGeometryMargin = 2;

// Placeholder geometry: a link whose geometry's half-diagonal is below this (a 1 mm sphere, a
// zero-size box) has no size to judge its inertia by. Dummy masses: a link of at most this mass
// (0.1 to 1 g markers, frames given a token mass so that a parser accepts them) is not a body
// whose inertia matters; the geometry rules say nothing about either.
constexpr double kPlaceholderHalfDiagonal = 0.005;  // metres
constexpr double kDummyMass = 1e-3;                 // kg
constexpr double kMarkerHalfDiagonal = 0.01;        // metres: a 1 cm cube is 0.00866
// Where part of a welded group's geometry is a mesh of unknown size, the known geometry may cover
// only part of the body: the geometry rules allow it to reach this many times farther.
constexpr double kPartialGeometryMargin = 3;
// A typed-in inertia on a link with nothing to judge it by matters when it is at least this share
// of its welded group's central inertia (an error of 5% in a body's inertia is about what careful
// identification achieves, so more than that changes what a controller sees).
constexpr double kMadeUpInertiaShare = 0.05;

// massless-moving-body: a joint's generalized coordinate has zero inertia (the mass matrix is
// singular) when the inertia that its outboard bodies put on it is at most this fraction of its
// natural scale (see HingeInertiaOf). Far above the round-off of composing written numbers
// (about 1e-16 relative: a point mass written on the axis composes to 0 or ~1e-17), far below
// any real body (a 1 m, 1 kg arm would need its mass within 1 µm of the axis).
constexpr double kSingularTolerance = 1e-12;

std::string Format(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string Format(const char* format, ...) {
  char buffer[1024];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof(buffer), format, args);
  va_end(args);
  return buffer;
}

// A number as %g with 6 significant digits (enough to recognise the file's numbers).
std::string Num(double x) { return Format("%.6g", x); }

std::string Vec(const Eigen::Vector3d& v) {
  return "(" + Num(v.x()) + ", " + Num(v.y()) + ", " + Num(v.z()) + ")";
}

// The physical-validity facts of an inertia matrix at a center of mass.
struct Validity {
  bool finite = false;
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();  // ascending principal moments
  double trace = 0;
  double excess = 0;  // λ3 − (λ1 + λ2): positive when the triangle inequality fails
};

Validity Analyze(const Eigen::Matrix3d& I) {
  Validity v;
  v.finite = I.allFinite();
  if (!v.finite) return v;
  v.moments = internal::ScaledPrincipalMoments(I(0, 0), I(1, 1), I(2, 2), I(1, 0), I(2, 0), I(2, 1),
                                               PrincipalSolver::kAccurate);
  v.trace = I.trace();
  v.excess = v.moments(2) - (v.moments(0) + v.moments(1));
  return v;
}

bool IsValid(const Eigen::Matrix3d& I, double relative_tolerance) {
  return internal::IsPhysicallyValidInertia(I(0, 0), I(1, 1), I(2, 2), I(1, 0), I(2, 0), I(2, 1),
                                            relative_tolerance);
}

// "principal moments 0.1, 0.2, 0.5: 0.1 + 0.2 < 0.5 (by 0.2 = 25% of the trace)".
std::string DescribeViolation(const Validity& v) {
  const Eigen::Vector3d& m = v.moments;
  std::string text = "principal moments " + Num(m(0)) + ", " + Num(m(1)) + ", " + Num(m(2)) + ": ";
  if (m(0) < 0) text += "a negative moment, and ";
  text += Num(m(0)) + " + " + Num(m(1)) + " < " + Num(m(2)) + " (by " + Num(v.excess);
  if (v.trace > 0) {
    text += " = " + Format("%.3g%%", 100 * v.excess / v.trace) + " of the trace";
  }
  return text + ")";
}

// The values of a finding about the validity `v` of an inertia judged with `tolerance`.
std::vector<std::pair<std::string, double>> ValidityValues(const Validity& v, double tolerance) {
  return {
      {"principal_min", v.moments(0)}, {"principal_mid", v.moments(1)},
      {"principal_max", v.moments(2)}, {"trace", v.trace},
      {"violation", v.excess},         {"relative_violation", v.trace > 0 ? v.excess / v.trace : 0},
      {"tolerance", tolerance}};
}

Eigen::Matrix3d WrittenMatrix(const Inertial& in) {
  Eigen::Matrix3d I;
  I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  return I;
}

std::optional<GeometryBounds> BoundsOf(const Link& link, bool collision) {
  GeometryBounds bounds;
  bounds.from_collision = collision;
  for (const Geometry& g : link.geometries) {
    if (g.is_collision != collision) continue;
    const std::optional<Eigen::AlignedBox3d> box = CalcPrimitiveBounds(g);
    if (!box) return std::nullopt;
    bounds.box_B.extend(*box);
    ++bounds.count;
  }
  if (bounds.count == 0) return std::nullopt;
  return bounds;
}

// The half-diagonal that "too small" is judged against: the smaller of the link's collision and
// visual geometry when both are known primitives larger than a placeholder (either may be the
// body: gz-sim's entity_semantics.sdf has a 23.4 m collision sphere around a 1.2 m visual one);
// else that of `bounds`.
double SmallestGeometryExtent(const Link& link, const GeometryBounds& bounds) {
  double extent = 0.5 * bounds.box_B.diagonal().norm();
  const std::optional<GeometryBounds> collision = BoundsOf(link, /*collision=*/true);
  const std::optional<GeometryBounds> visual = BoundsOf(link, /*collision=*/false);
  if (!collision || !visual) return extent;
  for (const GeometryBounds* b : {&*collision, &*visual}) {
    const double e = 0.5 * b->box_B.diagonal().norm();
    if (e >= kPlaceholderHalfDiagonal) extent = std::min(extent, e);
  }
  return extent;
}

// A unit mistake and the factor by which it makes (k / k_expected)² too large.
struct UnitSlip {
  double factor;
  const char* text;
};
constexpr UnitSlip kUnitSlips[] = {
    {1e6, "the inertia looks like kg·mm² (1e6 too large): multiply it by 1e-6"},
    {1e4, "the inertia looks like kg·cm² (1e4 too large): multiply it by 1e-4"},
    {1e-3, "the mass looks like grams (1000 too large): divide it by 1000"},
    {1e-6, "the inertia looks 1e6 too small (converted from kg·mm² twice?)"},
};

// The unit slip whose factor is nearest to `factor` (= (k / k_expected)²), by power of ten.
const UnitSlip& NearestUnitSlip(double factor) {
  const UnitSlip* best = &kUnitSlips[0];
  for (const UnitSlip& c : kUnitSlips) {
    if (std::abs(std::log10(factor / c.factor)) < std::abs(std::log10(factor / best->factor))) {
      best = &c;
    }
  }
  return *best;
}

// Why a link's inertia cannot be judged by its geometry, or "" when it can: placeholder geometry
// (half-diagonal below kPlaceholderHalfDiagonal) or a dummy mass.
std::string UnjudgedBecause(const Link& link, const std::optional<GeometryBounds>& bounds) {
  if (bounds) {
    const double e = 0.5 * bounds->box_B.diagonal().norm();
    if (e < kPlaceholderHalfDiagonal) {
      return "its geometry is a placeholder (half-diagonal " + Num(e) + " m)";
    }
  }
  if (link.inertial && link.inertial->mass <= kDummyMass) {
    return "its mass " + Num(link.inertial->mass) + " kg is a dummy's";
  }
  return "";
}

// A number a person types in: one significant digit (1, 0.01, 5e-4), to 1e-9 relative.
bool IsRoundNumber(double x) {
  if (!(x > 0) || !std::isfinite(x)) return false;
  const double mantissa = x / std::pow(10.0, std::floor(std::log10(x)));
  return std::abs(mantissa - std::round(mantissa)) <= 1e-9 * mantissa;
}

// The mark of a typed-in placeholder inertia: no products and a diagonal of equal or round values
// (1, 1, 1; 0.001, 0.001, 0.001; 0.01, 0.02, 0.01). Returns the evidence, or "" when absent.
std::string PlaceholderPattern(const Eigen::Matrix3d& I) {
  if (I(0, 1) != 0 || I(0, 2) != 0 || I(1, 2) != 0) return "";
  const Eigen::Vector3d d = I.diagonal();
  const std::string diagonal = Num(d(0)) + ", " + Num(d(1)) + ", " + Num(d(2));
  if (d(0) == d(1) && d(1) == d(2)) return "the diagonal is " + diagonal + " with no products";
  if (IsRoundNumber(d(0)) && IsRoundNumber(d(1)) && IsRoundNumber(d(2))) {
    return "the diagonal is the round numbers " + diagonal + " with no products";
  }
  return "";
}

// PlaceholderPattern of a blanket placeholder only: equal moments and no products (1e-3, 1e-3,
// 1e-3). Unequal round values show a thought-out inertia (pr2's laser_tilt_link, 1e-4, 1e-6, 1e-4:
// its scanner's). "" when absent.
std::string BlanketPlaceholder(const Eigen::Matrix3d& I) {
  if (!(I(0, 0) == I(1, 1) && I(1, 1) == I(2, 2))) return "";
  return PlaceholderPattern(I);
}

// The close of a causes list: which of the two causes the numbers can show points where.
std::string Verdict(bool slip_fits, bool placeholder) {
  if (slip_fits && placeholder)
    return "; the numbers cannot tell the unit slip from the placeholder";
  if (slip_fits) return "; the numbers point to the unit slip";
  if (placeholder) return "; the numbers point to the placeholder";
  return "; nothing in the numbers points to one cause";
}

// The causes that fit a radius of gyration k (inertia I, mass m) that is `ratio` times the
// geometry's half-diagonal `extent`, with the evidence the numbers give for each. The numbers can
// point to a unit slip (one unit factor brings k/extent into the expected 0.3 to 1) and to a
// placeholder (typed-in values); they cannot confirm a mass edited without its inertia or values
// raised on purpose (always possible, so listed with what they would imply), and where two causes
// have evidence the message says that the numbers cannot tell them apart.
std::string Causes(const Eigen::Matrix3d& I, double m, double ratio, double extent) {
  const double k_expected = 0.5 * extent;  // a solid body filling its box: k ≈ 0.45–0.58·extent
  const double factor = ratio * ratio / 0.25;
  const UnitSlip& slip = NearestUnitSlip(factor);
  const double fixed_ratio = ratio / std::sqrt(slip.factor);
  const bool slip_fits = fixed_ratio >= 0.3 && fixed_ratio <= 1;
  const std::string placeholder = PlaceholderPattern(I);
  // The mass a solid of this size would need to carry this inertia: tr(I) = 2·m'·k_expected².
  const double fitting_mass = I.trace() / (2 * k_expected * k_expected);
  std::string text =
      "the causes that fit, and what the numbers say of each: a unit slip (" +
      std::string(slip.text) + (slip_fits ? ", which gives " : "; that gives ") + Num(fixed_ratio) +
      " times the half-diagonal" +
      (slip_fits ? ", in the expected range" : ", still out of range: no unit slip fits") +
      "); a placeholder inertia (" +
      (placeholder.empty() ? "no sign of one: the values are not typed-in round numbers"
                           : placeholder) +
      "); " +
      (ratio > 1 ? "a mass lowered without its inertia, or an inertia raised on purpose "
                   "(to stabilise a simulation) or copied from a bigger part"
                 : "a mass raised without its inertia") +
      " (possible whatever the numbers: this inertia is that of a solid of this size "
      "weighing " +
      Num(fitting_mass) + " kg; the link's mass is " + Num(m) + " kg)";
  return text + Verdict(slip_fits, !placeholder.empty());
}

// The causes that fit a radius of gyration k beyond kMaxGyrationRadiusWithoutGeometry on a link
// with no geometry of known size (inertia I): with no size to compare, a unit slip is judged by
// whether kg·mm² read as kg·m² brings k under a metre.
std::string CausesWithoutGeometry(const Eigen::Matrix3d& I, double k) {
  const std::string placeholder = PlaceholderPattern(I);
  const bool slip_fits = k / 1000 <= 1;
  std::string text =
      "the causes that fit, and what the numbers say of each: a unit slip (an "
      "inertia in kg·mm² would make it " +
      Num(k / 1000) + " m" + (slip_fits ? ", a body's size" : ", still too large") +
      "); a placeholder inertia (" +
      (placeholder.empty() ? "no sign of one: the values are not typed-in round numbers"
                           : placeholder) +
      "); an inertia raised on purpose (possible whatever the numbers)";
  return text + Verdict(slip_fits, !placeholder.empty());
}

// A mesh 1000 times too large (an STL in millimetres referenced without scale="0.001 ...") makes
// a right inertia look 1e6 too small: say so when the geometry is a mesh and k/e is near 1/1000
// of a solid body's 0.5.
std::string MeshScaleHint(const GeometryBounds& bounds, double ratio) {
  if (!bounds.from_mesh || !(ratio < 0.5 / 100)) return "";
  return "; or the mesh is in millimetres and lacks scale=\"0.001 0.001 0.001\" (its box is " +
         Format("%.3g", 0.5 / ratio) + " times the size the radius of gyration suggests)";
}

// What the bodies outboard of a joint give its generalized coordinates (massless-moving-body).
//
// With only joint J moving, at rates q̇ (every other joint still), the bodies inboard of J stay at
// rest and the kinetic energy is that of the bodies outboard of J (its child and all their
// descendants: composite mass m, center of mass c, central inertia I_cm, all in J's frame C, whose
// origin O lies on the axis): T = ½ q̇ᵀ M_JJ q̇ with M_JJ = S_Jᵀ 𝕀_O S_J, 𝕀_O their composite spatial
// inertia about O and S_J the joint's motion subspace. M_JJ is J's diagonal block of the mass
// matrix M, and M is positive semi-definite: if vᵀ M_JJ v = 0 for some v ≠ 0, the generalized
// velocity that is v on J and 0 elsewhere has zero kinetic energy, so M·(v, 0) = 0 and M is
// singular. (The converse needs more than diagonal blocks: two coaxial revolute joints through a
// massless link make M singular with every M_JJ > 0; that case is not detected here.)
//  - revolute/continuous, unit axis a through O: S = (a; 0), M_JJ = a·I_O·a with
//    I_O = I_cm + m·(|c|²·1 − c·cᵀ); zero when everything outboard lies on the axis line (a point
//    mass on it, a rod along it). Scale: tr(I_O) = tr(I_cm) + 2·m·|c|², the outboard composite's
//    own size about O (mass × extent² + trace): singular when a·I_O·a <=
//    kSingularTolerance·tr(I_O), scale-free, and true for any tr(I_O) when a·I_O·a = 0.
//  - prismatic: S = (0; a), M_JJ = m. Scale: the model's total mass.
//  - ball: S = (1; 0), M_JJ = I_O: singular when its smallest eigenvalue is zero (scale tr(I_O)).
//  - planar (normal a): two translations ⊥ a and a turn about a; det M_JJ = m²·(a·I_cm·a) (Schur
//    complement of the translational block m·1): zero mass or a·I_cm·a = 0 (scale tr(I_cm)).
//  - floating, and a free SDF link: M_JJ is the 6×6 spatial inertia, det M_JJ = m³·det(I_cm): zero
//    mass or a singular central inertia (a point mass, a rod; scale tr(I_cm)).
//  - other types (universal, screw, unknown): judged on the mass only.
// Every type first needs m > kSingularTolerance·(the model's total mass).
struct HingeInertia {
  bool singular = false;
  double mass = 0;    // outboard mass
  double moment = 0;  // the rotational inertia judged (a·I_O·a, a smallest moment), if any
  std::string why;    // singular: what has no inertia; regular: the rotational inertia judged
};

double SmallestMoment(const Eigen::Matrix3d& I) {
  return internal::ScaledPrincipalMoments(I(0, 0), I(1, 1), I(2, 2), I(1, 0), I(2, 0), I(2, 1),
                                          PrincipalSolver::kAccurate)(0);
}

HingeInertia HingeInertiaOf(Joint::Type type, const Eigen::Vector3d& axis_C,
                            const CompositeInertia& outboard, double total_mass) {
  HingeInertia h;
  h.mass = outboard.mass;
  if (!(outboard.mass > kSingularTolerance * total_mass)) {
    h.singular = true;
    h.why = "nothing outboard of it has mass (outboard mass " + Num(outboard.mass) + " kg)";
    return h;
  }
  const Eigen::Matrix3d I_O = outboard.CalcInertiaAboutOrigin();
  const Eigen::Matrix3d& I_cm = outboard.I_SScm_R;
  const double norm = axis_C.norm();
  const Eigen::Vector3d a = norm > 0 ? Eigen::Vector3d(axis_C / norm) : Eigen::Vector3d::UnitZ();
  double scale = 0;
  if ((type == Joint::Type::kRevolute || type == Joint::Type::kContinuous) && norm > 0) {
    h.moment = a.dot(I_O * a);
    scale = I_O.trace();
    h.why = "moment of inertia about the joint axis " + Vec(a) + " through the joint origin";
  } else if (type == Joint::Type::kBall) {
    h.moment = SmallestMoment(I_O);
    scale = I_O.trace();
    h.why = "smallest principal moment of inertia about the joint center";
  } else if (type == Joint::Type::kPlanar && norm > 0) {
    h.moment = a.dot(I_cm * a);
    scale = I_cm.trace();
    h.why = "moment of inertia about the plane's normal " + Vec(a) + " through its center of mass";
  } else if (type == Joint::Type::kFloating) {
    h.moment = SmallestMoment(I_cm);
    scale = I_cm.trace();
    h.why = "smallest principal moment of inertia about its center of mass";
  } else {
    h.why.clear();
    return h;
  }
  h.singular = h.moment <= kSingularTolerance * scale;
  h.why = h.singular ? "everything outboard of it (mass " + Num(outboard.mass) +
                           " kg) gives the joint no inertia: its " + h.why + " is " +
                           Num(h.moment) + " kg·m²"
                     : h.why + " " + Num(h.moment) + " kg·m²";
  return h;
}

class Checker {
 public:
  Checker(const Model& model, const CheckOptions& options) : model_(model), options_(options) {}

  std::vector<Finding> Run() {
    groups_ = FindWeldedGroups(model_);
    group_of_.assign(model_.links.size(), -1);
    for (std::size_t g = 0; g < groups_.size(); ++g) {
      for (int i : groups_[g].links) group_of_[i] = static_cast<int>(g);
    }
    BuildJointTree();
    sdf_without_inertials_ = model_.format == Model::Format::kSdf && !model_.links.empty();
    for (const Link& link : model_.links) {
      sdf_without_inertials_ =
          sdf_without_inertials_ && !link.inertial && !link.inertial_unreadable;
    }
    for (std::size_t i = 0; i < model_.links.size(); ++i) CheckLink(static_cast<int>(i));
    kinematic_only_ = model_.format == Model::Format::kUrdf;
    for (const Link& link : model_.links) kinematic_only_ = kinematic_only_ && !link.inertial;
    if (kinematic_only_) {
      CheckKinematicOnlyModel();
    } else {
      for (const WeldedGroup& group : groups_) CheckGroup(group);
    }
    std::stable_sort(findings_.begin(), findings_.end(), [](const Finding& a, const Finding& b) {
      if (a.location.line != b.location.line) return a.location.line < b.location.line;
      return a.rule < b.rule;
    });
    return std::move(findings_);
  }

 private:
  // children_[l]: (child link, joint) of every joint from link l that is its child's tree parent
  // joint (the first in file order, as FindWeldedGroups decides); total_mass_: the model's mass.
  void BuildJointTree() {
    children_.assign(model_.links.size(), {});
    // Names hashed once (Model::FindLink and FindParentJoint search linearly: per joint, that
    // would make a chain of n links cost n^2).
    std::unordered_map<std::string_view, int> link_of;
    link_of.reserve(model_.links.size());
    for (std::size_t i = 0; i < model_.links.size(); ++i) {
      link_of.emplace(model_.links[i].name, static_cast<int>(i));  // the first of a name
    }
    std::unordered_set<std::string_view> has_parent_joint;
    has_parent_joint.reserve(model_.joints.size());
    for (std::size_t j = 0; j < model_.joints.size(); ++j) {
      const Joint& joint = model_.joints[j];
      // The tree parent joint of a link is the first joint naming it as child.
      if (!has_parent_joint.insert(joint.child).second) continue;
      const auto p = link_of.find(joint.parent), c = link_of.find(joint.child);
      if (p == link_of.end() || c == link_of.end()) continue;
      children_[p->second].emplace_back(c->second, static_cast<int>(j));
    }
    total_mass_ = 0;
    for (const Link& link : model_.links) {
      const double m = LinkMassProperties(link, model_.format).mass;
      if (m > 0 && std::isfinite(m)) total_mass_ += m;
    }
  }

  // The composite of link `child_link` and everything outboard of it (its welded group and every
  // group attached below, through any joint, at the zero configuration), about and expressed in
  // `child_link`'s frame; nullopt when a member's <inertial> could not be read.
  std::optional<CompositeInertia> OutboardComposite(int child_link) const {
    std::vector<MassProperties> parts;
    std::vector<std::pair<int, Pose>> stack = {{child_link, Pose()}};
    std::vector<bool> seen(model_.links.size(), false);
    while (!stack.empty()) {
      const auto [l, X_CL] = stack.back();
      stack.pop_back();
      if (seen[l]) continue;
      seen[l] = true;
      const Link& link = model_.links[l];
      if (link.inertial_unreadable) return std::nullopt;
      const MassProperties props_L = LinkMassProperties(link, model_.format);
      if (props_L.mass != 0 || !props_L.I_SScm_F.isZero(0)) {
        MassProperties props_C;
        props_C.mass = props_L.mass;
        props_C.p_FoScm_F = X_CL.p_AB + X_CL.R_AB * props_L.p_FoScm_F;
        props_C.I_SScm_F = X_CL.R_AB * props_L.I_SScm_F * X_CL.R_AB.transpose();
        parts.push_back(props_C);
      }
      for (const auto& [c, j] : children_[l]) stack.emplace_back(c, X_CL * model_.joints[j].X_PC);
    }
    return ComposeMassProperties(parts);
  }

  // The severity of `rule` after the overrides, or nullopt when the rule is off.
  std::optional<Severity> SeverityOf(const char* rule) const {
    const auto it = options_.overrides.find(rule);
    if (it != options_.overrides.end()) return it->second;
    for (const RuleInfo& info : AllRules()) {
      if (info.id == rule) {
        return info.enabled_by_default ? std::optional<Severity>(info.default_severity)
                                       : std::nullopt;
      }
    }
    return std::nullopt;
  }

  bool Enabled(const char* rule, const Link& link) const {
    for (const std::string& ignored : link.ignored_rules) {
      if (ignored == "all" || ignored == rule) return false;
    }
    return SeverityOf(rule).has_value();
  }

  void Emit(const char* rule, const Link& link, const SourceLocation& location, std::string message,
            std::vector<std::pair<std::string, double>> values) {
    if (!Enabled(rule, link)) return;
    Finding f;
    f.rule = rule;
    f.severity = *SeverityOf(rule);
    f.model = model_.name;
    f.link = link.name;
    f.location = location;
    f.message = std::move(message);
    f.values = std::move(values);
    findings_.push_back(std::move(f));
  }

  // The <inertia> element if present, else the <inertial>, else the <link>.
  static const SourceLocation& InertiaLocation(const Link& link) {
    if (link.inertial) {
      if (link.inertial->inertia_location.line > 0) return link.inertial->inertia_location;
      if (link.inertial->location.line > 0) return link.inertial->location;
    }
    return link.location;
  }
  static const SourceLocation& MassLocation(const Link& link) {
    if (link.inertial && link.inertial->mass_location.line > 0) {
      return link.inertial->mass_location;
    }
    return InertiaLocation(link);
  }
  static const SourceLocation& PoseLocation(const Link& link) {
    if (link.inertial && link.inertial->pose_location.line > 0) {
      return link.inertial->pose_location;
    }
    return InertiaLocation(link);
  }

  // A link with a positive mass, and the geometry its inertia and center of mass are judged by.
  struct JudgedLink {
    const Link* link = nullptr;
    int index = -1;
    std::string who;            // "link 'name'"
    bool valid = false;         // the written inertia is valid within the tolerance
    Eigen::Matrix3d I_written;  // as written: about the center of mass, in the inertial frame
    MassProperties props;       // about the center of mass, in the link frame
    // The link as a solid of its geometry (primitives; meshes through options_.shape).
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
  };

  // Every per-link rule on link `link_index`, in the order they are judged.
  void CheckLink(int link_index) {
    const Link& link = model_.links[link_index];
    if (!link.inertial) return;  // inertial-missing is judged with the link's group.
    const std::string who = "link '" + link.name + "'";
    CheckMassFinite(link, who);
    if (!CheckInertialFinite(link, who)) return;
    const bool valid = CheckInertiaValidity(link_index, who);
    const double m = link.inertial->mass;
    if (!(m > 0) || !std::isfinite(m)) return;

    // A static SDF model never moves: the simulator never uses its mass properties, so the
    // heuristics (what a simulation would get wrong) have nothing to say (gz-sim's conveyor.sdf).
    if (model_.is_static) return;
    const JudgedLink judged = JudgeAgainstGeometry(link_index, who, valid);
    CheckProductsSignAgainstGeometry(judged);
    const bool units_flagged = CheckUnits(judged) || CheckMadeUpInertia(judged);
    if (!judged.group_bounds) return;
    if (valid && !units_flagged) CheckInertiaFitsGeometry(judged);
    CheckComInsideGeometry(judged);
  }

  // mass-not-positive: a negative, NaN or infinite mass.
  void CheckMassFinite(const Link& link, const std::string& who) {
    const double m = link.inertial->mass;
    if (!std::isfinite(m) || m < 0) {
      Emit(kMassNotPositive, link, MassLocation(link),
           who + ": mass " + Num(m) + " is " + (std::isfinite(m) ? "negative" : "not finite") +
               " (a mass must be a finite number >= 0; 0 only for a massless frame welded to a "
               "body)",
           {{"mass", m}});
    }
  }

  // inertia-not-finite; returns whether the inertia and the inertial's pose are all finite.
  bool CheckInertialFinite(const Link& link, const std::string& who) {
    const Inertial& in = *link.inertial;
    const Eigen::Matrix3d I_written = WrittenMatrix(in);
    if (I_written.allFinite() && in.X_BBi.p_AB.allFinite() && in.X_BBi.R_AB.allFinite()) {
      return true;
    }
    Emit(kInertiaNotFinite, link, InertiaLocation(link),
         who + ": the inertial has a NaN or infinite number: ixx " + Num(in.ixx) + ", iyy " +
             Num(in.iyy) + ", izz " + Num(in.izz) + ", ixy " + Num(in.ixy) + ", ixz " +
             Num(in.ixz) + ", iyz " + Num(in.iyz) + ", center of mass " + Vec(in.X_BBi.p_AB),
         {{"ixx", in.ixx},
          {"iyy", in.iyy},
          {"izz", in.izz},
          {"ixy", in.ixy},
          {"ixz", in.ixz},
          {"iyz", in.iyz}});
    return false;
  }

  // inertia-not-physical (and products-sign-suspect when negating the products makes it valid),
  // or inertia-near-boundary; returns whether the written inertia is valid within the tolerance.
  bool CheckInertiaValidity(int link_index, const std::string& who) {
    const Link& link = model_.links[link_index];
    const Eigen::Matrix3d I_written = WrittenMatrix(*link.inertial);
    // Validity does not depend on the frame the inertia is expressed in: judge the numbers as
    // written (about the center of mass, in the inertial frame), free of rotation round-off.
    const double tol = options_.tolerance;
    const bool valid = IsValid(I_written, tol);
    if (!valid) {
      const Validity v = Analyze(I_written);
      Emit(kInertiaNotPhysical, link, InertiaLocation(link),
           who + ": the inertia about the center of mass is not physically valid: " +
               DescribeViolation(v) + GroupNote(link_index),
           ValidityValues(v, tol));
      CheckProductsSignWhenInvalid(link, who);
    } else if (!IsValid(I_written, internal::DefaultInertiaValidityTolerance<double>())) {
      const Validity v = Analyze(I_written);
      Emit(kInertiaNearBoundary, link, InertiaLocation(link),
           who + ": the inertia is valid only within the tolerance " + Num(tol) +
               " of the trace: " + DescribeViolation(v) +
               " (the body is a thin shape, written with rounded numbers?)",
           ValidityValues(v, tol));
    }
    return valid;
  }

  // products-sign-suspect for an invalid inertia: valid with the products of inertia negated.
  void CheckProductsSignWhenInvalid(const Link& link, const std::string& who) {
    const Inertial& in = *link.inertial;
    const Eigen::Matrix3d I_written = WrittenMatrix(in);
    Eigen::Matrix3d I_negated = -I_written;
    I_negated.diagonal() = I_written.diagonal();
    if (!IsValid(I_negated, options_.tolerance)) return;
    const Validity vn = Analyze(I_negated);
    Emit(kProductsSignSuspect, link, InertiaLocation(link),
         who +
             ": the inertia is invalid as written but valid with the products of inertia "
             "negated (ixy, ixz, iyz = " +
             Num(in.ixy) + ", " + Num(in.ixz) + ", " + Num(in.iyz) +
             "; negated, the principal moments are " + Num(vn.moments(0)) + ", " +
             Num(vn.moments(1)) + ", " + Num(vn.moments(2)) +
             "): the exporter probably wrote +∫xy dm where URDF/SDF expect -∫xy dm",
         {{"ixy", in.ixy},
          {"ixz", in.ixz},
          {"iyz", in.iyz},
          {"negated_principal_min", vn.moments(0)},
          {"negated_principal_mid", vn.moments(1)},
          {"negated_principal_max", vn.moments(2)}});
  }

  // The mass properties of link `link_index` (of positive mass) and the geometry they are
  // judged by.
  JudgedLink JudgeAgainstGeometry(int link_index, const std::string& who, bool valid) const {
    const Link& link = model_.links[link_index];
    JudgedLink judged;
    judged.link = &link;
    judged.index = link_index;
    judged.who = who;
    judged.valid = valid;
    judged.I_written = WrittenMatrix(*link.inertial);
    judged.props = LinkMassProperties(link, model_.format);
    const Eigen::Vector3d& c = judged.props.p_FoScm_F;
    judged.shape = CalcLinkShape(link, options_.shape);
    std::optional<GeometryBounds>& bounds = judged.bounds;
    bounds = CalcLinkGeometryBounds(link, judged.shape, options_.box);
    // Placeholder geometry and dummy masses: nothing to judge by (see kPlaceholderHalfDiagonal).
    judged.unjudged_because = UnjudgedBecause(link, bounds);
    if (!judged.unjudged_because.empty()) bounds.reset();
    // A visual-only marker (no collision; a box of at most kMarkerHalfDiagonal drawn to show a
    // frame, as PR2, Cassie and Atlas do) shows where the link is, not how far its body reaches:
    // like a mesh of unknown size, it is partial (Cassie's motor rotors, 0.27 kg with k = 3.5 cm,
    // behind 1 cm marker boxes).
    if (bounds && !bounds->from_collision &&
        0.5 * bounds->box_B.diagonal().norm() < kMarkerHalfDiagonal) {
      bounds->partial = true;
    }
    if (bounds) judged.smallest_extent = SmallestGeometryExtent(link, *bounds);
    // A mass lumped onto one link of a welded group shows as a center of mass outside the link's
    // own geometry: such a link is judged against the geometry of the whole group (in this link's
    // frame); any other link against its own (collision and visual).
    judged.group_bounds = bounds;
    if (bounds) {
      const Eigen::Vector3d h_own = 0.5 * bounds->box_B.sizes();
      const Eigen::Vector3d out_own =
          ((c - bounds->box_B.center()).cwiseAbs() - h_own).cwiseMax(Eigen::Vector3d::Zero());
      if (out_own.norm() > (kGeometryMargin - 1) * h_own.norm()) {
        judged.group_bounds = GroupBounds(link_index, *bounds);
      }
    }
    judged.geometry_name = std::string(bounds && !bounds->from_collision ? "visual" : "collision") +
                           (bounds && bounds->from_mesh ? " mesh" : "");
    return judged;
  }

  // products-sign-suspect for an inertia valid both ways: the geometry decides.
  void CheckProductsSignAgainstGeometry(const JudgedLink& judged) {
    if (!judged.valid || !judged.shape) return;
    const Link& link = *judged.link;
    const Inertial& in = *link.inertial;
    Eigen::Matrix3d I_negated = -judged.I_written;
    I_negated.diagonal() = judged.I_written.diagonal();
    const std::optional<ProductsSignEvidence> evidence =
        FindProductsSignEvidence(in, *judged.shape);
    if (!evidence || !IsValid(I_negated, options_.tolerance)) return;
    const Eigen::Vector3d& g = evidence->geometry_products;
    Emit(kProductsSignSuspect, link, InertiaLocation(link),
         judged.who + ": the products of inertia (ixy, ixz, iyz = " + Num(in.ixy) + ", " +
             Num(in.ixz) + ", " + Num(in.iyz) + ") have the opposite sign of those its " +
             judged.geometry_name + " geometry implies for its mass (" + Num(g.x()) + ", " +
             Num(g.y()) + ", " + Num(g.z()) + "; negated they differ by " +
             Format("%.2g%%", 100 * evidence->mismatch_negated) + ", as written by " +
             Format("%.3g%%", 100 * evidence->mismatch_as_written) +
             "): they were probably written as +∫xy dm where URDF/SDF expect -∫xy dm, or "
             "copied from a mirror-image part",
         {{"ixy", in.ixy},
          {"ixz", in.ixz},
          {"iyz", in.iyz},
          {"geometry_ixy", g.x()},
          {"geometry_ixz", g.y()},
          {"geometry_iyz", g.z()},
          {"cosine", evidence->cosine},
          {"mismatch_as_written", evidence->mismatch_as_written},
          {"mismatch_negated", evidence->mismatch_negated}});
  }

  // units-suspect; returns whether it was flagged.
  bool CheckUnits(const JudgedLink& judged) {
    const Link& link = *judged.link;
    const double m = link.inertial->mass;
    const double trace = judged.I_written.trace();
    if (!(trace > 0)) return false;
    const double k = std::sqrt(trace / (2 * m));
    if (!judged.bounds) {
      if (!(k > kMaxGyrationRadiusWithoutGeometry)) return false;
      Emit(kUnitsSuspect, link, InertiaLocation(link),
           judged.who + ": radius of gyration sqrt(tr(I)/(2m)) = " + Num(k) + " m is beyond " +
               Num(kMaxGyrationRadiusWithoutGeometry) +
               " m (the link has no geometry of known size): " +
               CausesWithoutGeometry(judged.I_written, k),
           {{"radius_of_gyration", k}, {"mass", m}, {"trace", trace}});
      return true;
    }
    const double extent = 0.5 * judged.bounds->box_B.diagonal().norm();
    if (!(extent > 0)) return false;
    const double ratio = k / extent;
    const double group_extent = 0.5 * judged.group_bounds->box_B.diagonal().norm();
    // Too large only against the whole group's known geometry; too small against the link's
    // smaller geometry set (collision or visual, whichever is smaller, when both are known).
    const bool too_large = ratio > kUnitsRatio && k / group_extent > kUnitsRatio;
    const bool too_small = k / judged.smallest_extent < 1 / kUnitsRatio;
    if (!(too_large || too_small)) return false;
    // A solid body filling its box has k ≈ 0.5·extent: judge the factor against that.
    Emit(kUnitsSuspect, link, InertiaLocation(link),
         judged.who + ": radius of gyration sqrt(tr(I)/(2m)) = " + Num(k) + " m is " + Num(ratio) +
             " times the half-diagonal " + Num(extent) + " m of its " + judged.geometry_name +
             " geometry (expected " + "about 0.3 to 1): " +
             Causes(judged.I_written, m, ratio, extent) + MeshScaleHint(*judged.bounds, ratio),
         {{"radius_of_gyration", k},
          {"geometry_half_diagonal", extent},
          {"ratio", ratio},
          {"mass", m},
          {"trace", trace}});
    return true;
  }

  // units-suspect for a link the ratio test cannot judge (placeholder geometry, a dummy mass):
  // such links are left alone because they do not matter, which holds only if their inertia does
  // not either. Flags a typed-in isotropic inertia (PlaceholderPattern) that is at least
  // kMadeUpInertiaShare of its welded group's central inertia (the group has other members with
  // mass): numbers no body backs that change the group's dynamics (pr2's 1 g accelerometers with
  // I = 1e-3 kg·m², 8% of the gripper palm group; 0.1 kg cameras with I = 0.01 kg·m²).
  bool CheckMadeUpInertia(const JudgedLink& judged) {
    if (judged.bounds || judged.unjudged_because.empty()) return false;
    const std::string pattern = BlanketPlaceholder(judged.I_written);
    if (pattern.empty()) return false;
    const Link& link = *judged.link;
    const WeldedGroup& group = groups_[group_of_[judged.index]];
    if (group.links.size() < 2) return false;
    const CompositeInertia composite = CalcCompositeInertia(model_, group);
    const double total = composite.I_SScm_R.trace();
    if (!(composite.mass > link.inertial->mass) || !(total > 0)) return false;
    // The made-up inertias of a group add up: judge their sum (pr2's head carries eleven frames
    // with I = 1e-3 or 1e-2 kg·m², each a few percent of the head, together three times its own).
    double made_up = 0;
    int others = 0;
    for (int i : group.links) {
      const Link& member = model_.links[i];
      if (!member.inertial || !(member.inertial->mass > 0)) continue;
      if (i != judged.index) {
        if (BlanketPlaceholder(WrittenMatrix(*member.inertial)).empty() ||
            UnjudgedBecause(member, CalcLinkGeometryBounds(member)).empty()) {
          continue;
        }
        ++others;
      }
      made_up += WrittenMatrix(*member.inertial).trace();
    }
    const double share = made_up / total;
    if (!(share >= kMadeUpInertiaShare)) return false;
    const double own = judged.I_written.trace();
    const double m = link.inertial->mass;
    const double k = std::sqrt(own / (2 * m));
    Emit(kUnitsSuspect, link, InertiaLocation(link),
         judged.who + ": " + judged.unjudged_because + " and " + pattern + ", yet this inertia" +
             (others ? " with that of " + std::to_string(others) + " other such link" +
                           (others == 1 ? "" : "s") + " of its welded group"
                     : std::string()) +
             " is " + Format("%.3g%%", 100 * share) + " of the group's (trace " + Num(made_up) +
             " of " + Num(total) +
             " kg·m² about the group's center of mass; this link's radius "
             "of gyration " +
             Num(k) +
             " m): typed-in numbers that no body backs change the group's dynamics; give the "
             "link the inertia of its part (or zero, if it is only a frame)",
         {{"radius_of_gyration", k},
          {"mass", m},
          {"trace", own},
          {"group_share", share},
          {"other_links", others}});
    return true;
  }

  // The "too large" verdicts of the geometry rules are made against the group's known geometry;
  // where some of it is of unknown size (a mesh not read), the body may reach farther: the
  // allowance is then kPartialGeometryMargin times larger.
  static double Allowance(const GeometryBounds& group_bounds) {
    return group_bounds.partial ? kPartialGeometryMargin : 1.0;
  }

  // inertia-exceeds-geometry / inertia-about-origin-suspect (valid inertias only). A body inside
  // the box lies inside the box's circumscribed sphere (center o, radius r = half-diagonal), so
  // ∫|x − o|² dm = tr(Σ_o) <= m·r² (Wensing, Kim, Slotine 2017, with the ellipsoid Q = r²·1).
  void CheckInertiaFitsGeometry(const JudgedLink& judged) {
    const Link& link = *judged.link;
    const double m = link.inertial->mass;
    const double tol = options_.tolerance;
    const Eigen::Vector3d& c = judged.props.p_FoScm_F;
    const Eigen::Matrix3d& I_B = judged.props.I_SScm_F;
    const double allowance = Allowance(*judged.group_bounds);
    const Eigen::Vector3d o = judged.group_bounds->box_B.center();
    const Eigen::Vector3d h = 0.5 * judged.group_bounds->box_B.sizes();
    const double scale2 = h.squaredNorm();
    const std::string& geometry_kind = judged.geometry_name;
    const double r2 = allowance * allowance * kGeometryMargin * kGeometryMargin * scale2;
    const Eigen::Vector3d d = c - o;
    // tr(Σ_o) = tr(Σ_cm) + m·|d|² = ½·tr(I) + m·|d|².
    const double spread = 0.5 * I_B.trace() + m * d.squaredNorm();
    const double bound = m * r2;
    if (!(spread - bound > tol * bound)) return;
    // Would the numbers fit as the inertia about the link origin Bo? Then I_Bcm = I − m·(|c|²1
    // − c·cᵀ) must be valid and fit the sphere.
    const Eigen::Matrix3d I_shifted =
        I_B - m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
    const double shifted_spread = 0.5 * I_shifted.trace() + m * d.squaredNorm();
    const bool shifted_fits =
        !c.isZero(0) && IsValid(I_shifted, tol) && shifted_spread - bound <= tol * bound;
    if (shifted_fits) {
      const Validity vs = Analyze(I_shifted);
      Emit(kInertiaAboutOriginSuspect, link, InertiaLocation(link),
           judged.who + ": the inertia needs more room than the " + geometry_kind +
               " geometry gives (∫|x - o|² dm = " + Num(spread) + " > m·r² = " + Num(bound) +
               " kg·m² about the center o of its bounding box, r = " +
               Num(allowance * kGeometryMargin) + " × half-diagonal = " + Num(std::sqrt(r2)) +
               " m), but taken as the inertia about the link origin and shifted to the center "
               "of mass " +
               Vec(c) + " it is valid and fits (principal moments " + Num(vs.moments(0)) + ", " +
               Num(vs.moments(1)) + ", " + Num(vs.moments(2)) +
               "): it was probably written about the link origin",
           {{"spread", spread},
            {"bound", bound},
            {"shifted_spread", shifted_spread},
            {"shifted_principal_min", vs.moments(0)},
            {"shifted_principal_mid", vs.moments(1)},
            {"shifted_principal_max", vs.moments(2)}});
    } else {
      Emit(kInertiaExceedsGeometry, link, InertiaLocation(link),
           judged.who + ": no mass distribution inside the bounding box of the " + geometry_kind +
               " geometry (center " + Vec(o) + ", half-sizes " + Vec(h) +
               " m) has this inertia: ∫|x - o|² dm = tr(I)/2 + m·|c - o|² = " + Num(spread) +
               " kg·m² exceeds m·r² = " + Num(bound) + " kg·m² (r = " +
               Num(allowance * kGeometryMargin) + " × half-diagonal = " + Num(std::sqrt(r2)) +
               " m, allowing for simplified geometry; ratio " + Num(spread / bound) + ")",
           {{"spread", spread},
            {"bound", bound},
            {"ratio", spread / bound},
            {"half_diagonal", std::sqrt(r2)}});
    }
  }

  // com-outside-geometry.
  void CheckComInsideGeometry(const JudgedLink& judged) {
    const Link& link = *judged.link;
    const GeometryBounds& group_bounds = *judged.group_bounds;
    const Eigen::Vector3d& c = judged.props.p_FoScm_F;
    const double allowance = Allowance(group_bounds);
    const Eigen::Vector3d o = group_bounds.box_B.center();
    const Eigen::Vector3d h = 0.5 * group_bounds.box_B.sizes();
    const double scale2 = h.squaredNorm();
    const Eigen::Vector3d outside = ((c - o).cwiseAbs() - h).cwiseMax(Eigen::Vector3d::Zero());
    const double distance = outside.norm();
    const double allowed = allowance * (kGeometryMargin - 1) * std::sqrt(scale2);
    if (!(distance - allowed > options_.tolerance * std::sqrt(scale2))) return;
    Emit(kComOutsideGeometry, link, PoseLocation(link),
         judged.who + ": the center of mass " + Vec(c) + " is " + Num(distance) +
             " m outside the bounding box " + Vec(group_bounds.box_B.min()) + " to " +
             Vec(group_bounds.box_B.max()) + " of its " + judged.geometry_name +
             " geometry, farther than its half-diagonal " + Num(allowed) + " m",
         {{"com_x", c.x()},
          {"com_y", c.y()},
          {"com_z", c.z()},
          {"distance", distance},
          {"allowed", allowed}});
  }

  // The union of the known geometry (collision and visual) of every link of `link_index`'s welded
  // group, in that link's frame, starting from the link's own `bounds`. Partial when a member's
  // geometry size is not known (meshes).
  std::optional<GeometryBounds> GroupBounds(int link_index, const GeometryBounds& bounds) const {
    GeometryBounds result = bounds;
    const WeldedGroup& group = groups_[group_of_[link_index]];
    Pose X_RL;
    for (std::size_t k = 0; k < group.links.size(); ++k) {
      if (group.links[k] == link_index) X_RL = group.X_RL[k];
    }
    const Pose X_LR = X_RL.Inverse();
    for (std::size_t k = 0; k < group.links.size(); ++k) {
      const int j = group.links[k];
      if (j == link_index) continue;
      const Link& member = model_.links[j];
      if (member.geometries.empty()) continue;
      const std::optional<GeometryBounds>& b = BoundsOfLink(j);
      if (!b) {
        result.partial = true;
        continue;
      }
      result.partial |= b->partial;
      const Pose X_LM = X_LR * group.X_RL[k];
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d p =
            b->box_B.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
        result.box_B.extend(X_LM.p_AB + X_LM.R_AB * p);
      }
    }
    return result;
  }

  // The known extent of link `link_index`'s geometry (primitives, and mesh boxes through
  // options_.box), computed once per link: a link is looked at by each member of its group.
  const std::optional<GeometryBounds>& BoundsOfLink(int link_index) const {
    if (bounds_of_link_.empty()) bounds_of_link_.resize(model_.links.size());
    std::optional<std::optional<GeometryBounds>>& memo = bounds_of_link_[link_index];
    if (!memo) memo = CalcLinkGeometryBounds(model_.links[link_index], std::nullopt, options_.box);
    return *memo;
  }

  // Whether `box` (in the frame of link `link_index`) lies, or may lie, inside the geometry of
  // another member of `group` that has a positive mass.
  bool InsideMassiveNeighbour(const WeldedGroup& group, int link_index,
                              const Eigen::AlignedBox3d& box) const {
    Pose X_RL;
    for (std::size_t k = 0; k < group.links.size(); ++k) {
      if (group.links[k] == link_index) X_RL = group.X_RL[k];
    }
    const Pose X_LR = X_RL.Inverse();
    for (std::size_t k = 0; k < group.links.size(); ++k) {
      const Link& member = model_.links[group.links[k]];
      if (group.links[k] == link_index || !member.inertial || !(member.inertial->mass > 0)) {
        continue;
      }
      const std::optional<GeometryBounds>& b = BoundsOfLink(group.links[k]);
      // A neighbour with geometry of unknown size (a mesh not read) may hold the box: cannot
      // tell, say nothing.
      if (!member.geometries.empty() && (!b || b->partial)) return true;
      if (!b) continue;
      const Pose X_LM = X_LR * group.X_RL[k];
      Eigen::AlignedBox3d in_link;
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d p =
            b->box_B.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner));
        in_link.extend(X_LM.p_AB + X_LM.R_AB * p);
      }
      const double slack = 1e-9 * (1 + in_link.diagonal().norm());
      if ((box.min().array() >= in_link.min().array() - slack).all() &&
          (box.max().array() <= in_link.max().array() + slack).all()) {
        return true;
      }
    }
    return false;
  }

  // For an invalid member of a welded group: whether the group is valid as a whole.
  std::string GroupNote(int link_index) const {
    const WeldedGroup& group = groups_[group_of_[link_index]];
    if (group.links.size() < 2) return "";
    const CompositeInertia composite = CalcCompositeInertia(model_, group);
    if (composite.I_SScm_R.allFinite() && IsValid(composite.I_SScm_R, options_.tolerance)) {
      return "; its welded group rooted at '" + group.root_link +
             "' is valid as a whole (as a simulator that merges fixed joints sees it)";
    }
    return "";
  }

  // A URDF without any <inertial> describes kinematics only: one finding for the whole model
  // instead of one per moving body and one per link with collision geometry.
  void CheckKinematicOnlyModel() {
    int moving = 0;
    const WeldedGroup* first = nullptr;
    for (const WeldedGroup& group : groups_) {
      if (!group.is_moving) continue;
      ++moving;
      if (first == nullptr) first = &group;
    }
    if (first == nullptr) return;
    const Link& root = model_.links[first->links.front()];
    Emit(kMasslessMovingBody, root, root.location,
         "the model has no <inertial> at all (a kinematics-only description): its " +
             std::to_string(moving) + " moving bod" + (moving == 1 ? "y is" : "ies are") +
             " massless, starting with link '" + root.name + "'; a simulator cannot use it",
         {{"mass", 0}, {"moving_groups", static_cast<double>(moving)}});
  }

  // Every per-group rule on welded group `group`, in the order they are judged.
  void CheckGroup(const WeldedGroup& group) {
    // A static SDF model never moves: missing or zero mass properties are what it should have.
    if (model_.is_static) return;
    // A member whose <inertial> could not be read makes the group's mass properties unknown (the
    // reader's inertial-unreadable finding says why): judge nothing about the group.
    for (int i : group.links) {
      if (model_.links[i].inertial_unreadable) return;
    }
    const Link& root = model_.links[group.links.front()];
    const CompositeInertia composite = CalcCompositeInertia(model_, group);
    bool all_massless = true;
    const int contributing = CountContributingMembers(group, &all_massless);
    const std::string who = group.links.size() > 1
                                ? "the welded group rooted at '" + root.name + "' (" +
                                      std::to_string(group.links.size()) + " links)"
                                : "link '" + root.name + "'";
    const bool massless_moving = CheckMasslessMovingGroup(group, who, all_massless);
    if (!massless_moving) CheckInertialMissing(group);
    if (!composite.I_SScm_R.allFinite() || !std::isfinite(composite.mass)) return;
    CheckCompositeValidity(group, who, composite, contributing);
    CheckInertiaAboutJointAxis(group, who, composite);
  }

  // How many members of `group` contribute mass or inertia (SDF gives a link without <inertial>
  // mass 1); sets *all_massless to false when some member has a mass.
  int CountContributingMembers(const WeldedGroup& group, bool* all_massless) const {
    int contributing = 0;
    for (int i : group.links) {
      const Link& link = model_.links[i];
      if (!link.inertial) {
        if (model_.format == Model::Format::kSdf) {  // SDF default: mass 1, inertia diag(1,1,1).
          *all_massless = false;
          ++contributing;
        }
        continue;
      }
      if (link.inertial->mass != 0) *all_massless = false;
      if (link.inertial->mass != 0 || !WrittenMatrix(*link.inertial).isZero(0)) ++contributing;
    }
    return contributing;
  }

  // massless-moving-body (error) where a moving group without mass makes the mass matrix
  // singular (see HingeInertiaOf): what lies outboard of its joint gives the joint's coordinates
  // no inertia, or a joint it carries gets none; otherwise massless-link-with-mass-outboard (note).
  // Returns whether the group moves and has no mass.
  bool CheckMasslessMovingGroup(const WeldedGroup& group, const std::string& who,
                                bool all_massless) {
    if (!group.is_moving || !all_massless) return false;
    const int root_index = group.links.front();
    const Link& root = model_.links[root_index];
    Joint free;  // a free-floating SDF link moves as on a floating joint
    free.type = Joint::Type::kFloating;
    const Joint& joint = group.parent_joint >= 0 ? model_.joints[group.parent_joint] : free;
    const std::string how = group.parent_joint >= 0
                                ? "moves on " + joint.type_name + " joint '" + joint.name + "'"
                                : "is free-floating";
    const std::optional<CompositeInertia> outboard = OutboardComposite(root_index);
    // An outboard <inertial> unreadable or not finite: its own finding says so; nothing to judge.
    if (!outboard || !std::isfinite(outboard->mass) || !outboard->I_SScm_R.allFinite()) return true;
    const HingeInertia hinge = HingeInertiaOf(joint.type, joint.axis, *outboard, total_mass_);
    const std::vector<std::pair<std::string, double>> values = {
        {"mass", 0},
        {"outboard_mass", hinge.mass},
        {"moment_outboard", hinge.moment},
        {"group_links", static_cast<double>(group.links.size())}};
    const std::string singular =
        ": the mass matrix is singular (a joint coordinate has zero inertia), so simulators reject "
        "the model or become unstable";
    if (hinge.singular) {
      Emit(kMasslessMovingBody, root, MassLocation(root),
           who + " " + how + " but has zero mass, and " + hinge.why + singular, values);
      return true;
    }
    if (const std::optional<std::string> carried = SingularCarriedJoint(group)) {
      Emit(kMasslessMovingBody, root, MassLocation(root),
           who + " " + how + " but has zero mass, and " + *carried + singular, values);
      return true;
    }
    Emit(kMasslessWithMassOutboard, root, MassLocation(root),
         who + " " + how + " with zero mass, but " + Num(hinge.mass) + " kg lies outboard of it" +
             (hinge.why.empty() ? "" : " (" + hinge.why + ")") +
             ": the mass matrix is regular, so Drake and Pinocchio accept it; MuJoCo refuses a "
             "moving body whose mass is below mjMINVAL = 1e-15 unless its compiler options "
             "boundmass/boundinertia raise it (see `massprops check --target mujoco`)",
         values);
    return true;
  }

  // For a massless group: the first non-fixed joint from one of its links to a group with mass
  // whose outboard bodies give the joint's coordinates no inertia (why, in words), or nullopt. A
  // joint to a massless group is judged with that group.
  std::optional<std::string> SingularCarriedJoint(const WeldedGroup& group) const {
    for (int l : group.links) {
      for (const auto& [c, j] : children_[l]) {
        if (group_of_[c] == group_of_[l]) continue;  // a welded member
        bool child_massless = true;
        CountContributingMembers(groups_[group_of_[c]], &child_massless);
        if (child_massless) continue;
        const Joint& joint = model_.joints[j];
        const std::optional<CompositeInertia> outboard = OutboardComposite(c);
        if (!outboard || !std::isfinite(outboard->mass) || !outboard->I_SScm_R.allFinite())
          continue;
        const HingeInertia h = HingeInertiaOf(joint.type, joint.axis, *outboard, total_mass_);
        if (h.singular) {
          return "carries " + joint.type_name + " joint '" + joint.name + "', where " + h.why;
        }
      }
    }
    return std::nullopt;
  }

  // inertial-missing: links with collision geometry and no <inertial>.
  void CheckInertialMissing(const WeldedGroup& group) {
    // An SDF model none of whose links has an <inertial> is a kinematic or visual description
    // (sdformat's and gz-sim's frame and pose test models): one note for the model, not a warning
    // per link.
    if (sdf_without_inertials_) {
      NoteModelWithoutInertials(group);
      return;
    }
    double group_mass = 0;
    for (int i : group.links) {
      const Link& link = model_.links[i];
      if (link.inertial && std::isfinite(link.inertial->mass) && link.inertial->mass > 0) {
        group_mass += link.inertial->mass;
      }
    }
    for (int i : group.links) {
      const Link& link = model_.links[i];
      if (link.inertial) continue;
      int collisions = 0;
      for (const Geometry& g : link.geometries) collisions += g.is_collision ? 1 : 0;
      if (collisions == 0) continue;
      // Zero-size or 1 mm placeholder collisions on a frame link: nothing to give a mass to.
      const std::optional<GeometryBounds>& b = BoundsOfLink(i);
      if (b && !b->partial && 0.5 * b->box_B.diagonal().norm() < kPlaceholderHalfDiagonal) {
        continue;
      }
      // URDF: a collision-helper link whose geometry lies inside the geometry of a welded
      // neighbour that carries mass: that body's mass is given once, on the neighbour.
      if (model_.format == Model::Format::kUrdf && group_mass > 0 && b && !b->partial &&
          InsideMassiveNeighbour(group, i, b->box_B)) {
        continue;
      }
      Emit(kInertialMissing, link, link.location,
           "link '" + link.name + "' has " + std::to_string(collisions) + " collision geometr" +
               (collisions == 1 ? "y" : "ies") +
               " but no <inertial>: its mass was probably forgotten (" +
               (model_.format == Model::Format::kSdf
                    ? "SDF gives it the default mass 1 kg and inertia diag(1, 1, 1) kg·m²)"
                    : "URDF makes it massless)"),
           {{"collisions", collisions}});
    }
  }

  // model-without-inertials, once per model, on the first link with collision geometry.
  void NoteModelWithoutInertials(const WeldedGroup& group) {
    if (model_note_given_) return;
    for (int i : group.links) {
      const Link& link = model_.links[i];
      bool collision = false;
      for (const Geometry& g : link.geometries) collision = collision || g.is_collision;
      if (!collision) continue;
      model_note_given_ = true;
      const double links = static_cast<double>(model_.links.size());
      Emit(kModelWithoutInertials, link, link.location,
           "no link of model '" + model_.name + "' has an <inertial>: SDFormat gives each of its " +
               std::to_string(model_.links.size()) +
               " link(s) the default mass 1 kg and inertia diag(1, 1, 1) kg·m²; fine for a "
               "kinematic or visual model, wrong for a robot that is simulated",
           {{"links", links}});
      return;
    }
  }

  // inertia-not-physical for the group as one rigid body (when more than one member contributes).
  void CheckCompositeValidity(const WeldedGroup& group, const std::string& who,
                              const CompositeInertia& composite, int contributing) {
    if (contributing <= 1 || IsValid(composite.I_SScm_R, options_.tolerance)) return;
    const Link& root = model_.links[group.links.front()];
    const Validity v = Analyze(composite.I_SScm_R);
    std::vector<std::pair<std::string, double>> values = ValidityValues(v, options_.tolerance);
    values.emplace_back("group_links", static_cast<double>(group.links.size()));
    Emit(kInertiaNotPhysical, root, InertiaLocation(root),
         who + ": the composite inertia about the composite center of mass " +
             Vec(composite.p_RoScm_R) + " (mass " + Num(composite.mass) +
             ") is not physically valid: " + DescribeViolation(v),
         std::move(values));
  }

  // zero-inertia-about-joint-axis: a group turning on a revolute or continuous joint.
  void CheckInertiaAboutJointAxis(const WeldedGroup& group, const std::string& who,
                                  const CompositeInertia& composite) {
    if (group.parent_joint < 0 || !(composite.mass > 0)) return;
    const Link& root = model_.links[group.links.front()];
    const Joint& joint = model_.joints[group.parent_joint];
    if (joint.type != Joint::Type::kRevolute && joint.type != Joint::Type::kContinuous) return;
    const double norm = joint.axis.norm();
    if (!(norm > 0) || !joint.axis.allFinite()) return;
    const Eigen::Vector3d a = joint.axis / norm;
    const Eigen::Matrix3d I_Ro = composite.CalcInertiaAboutOrigin();
    const double I_axis = a.dot(I_Ro * a);
    if (I_axis <= options_.tolerance * I_Ro.trace()) {
      Emit(kZeroInertiaAboutJointAxis, root, InertiaLocation(root),
           who + " turns on " + joint.type_name + " joint '" + joint.name +
               "' but its moment of inertia about the joint axis " + Vec(a) + " is " + Num(I_axis) +
               " kg·m² (mass " + Num(composite.mass) +
               "): a torque would give it infinite angular acceleration",
           {{"moment_about_axis", I_axis},
            {"mass", composite.mass},
            {"trace", I_Ro.trace()},
            {"group_links", static_cast<double>(group.links.size())}});
    }
  }

  const Model& model_;
  const CheckOptions& options_;
  std::vector<WeldedGroup> groups_;
  std::vector<int> group_of_;                               // link index -> index into groups_
  std::vector<std::vector<std::pair<int, int>>> children_;  // see BuildJointTree
  double total_mass_ = 0;
  bool kinematic_only_ = false;
  bool sdf_without_inertials_ = false;  // an SDF model none of whose links has an <inertial>
  bool model_note_given_ = false;       // model-without-inertials said
  std::vector<Finding> findings_;
  mutable std::vector<std::optional<std::optional<GeometryBounds>>> bounds_of_link_;
};

}  // namespace

const char* ToString(Severity severity) {
  switch (severity) {
    case Severity::kNote:
      return "note";
    case Severity::kWarning:
      return "warning";
    case Severity::kError:
      return "error";
  }
  return "error";
}

std::optional<Severity> ParseSeverity(std::string_view text) {
  if (text == "note") return Severity::kNote;
  if (text == "warning") return Severity::kWarning;
  if (text == "error") return Severity::kError;
  return std::nullopt;
}

const std::vector<RuleInfo>& AllRules() {
  static const std::vector<RuleInfo> kRules = {
      {kMassNotPositive, Severity::kError, true,
       "An inertial's mass is negative, NaN or infinite."},
      {kInertiaNotFinite, Severity::kError, true,
       "An inertial has a NaN or infinite inertia entry or center of mass."},
      {kInertiaNotPhysical, Severity::kError, true,
       "At the center of mass, a principal moment is negative or the triangle inequality fails "
       "(per link and per welded group)."},
      {kMasslessMovingBody, Severity::kError, true,
       "A welded group that moves relative to its parent has zero mass, and nothing outboard "
       "gives its joint (or a joint it carries) inertia: the mass matrix is singular."},
      {kMasslessWithMassOutboard, Severity::kNote, true,
       "A massless moving welded group with mass outboard of it (a multi-axis joint's "
       "intermediate link): physics accepts it, MuJoCo does not without boundmass."},
      {kZeroInertiaAboutJointAxis, Severity::kWarning, true,
       "A revolute/continuous joint's child group has zero moment of inertia about the axis."},
      {kInertialMissing, Severity::kWarning, true,
       "A link has collision geometry but no <inertial>."},
      {kModelWithoutInertials, Severity::kNote, true,
       "No link of an SDF model has an <inertial> (a kinematic or visual model): said once, "
       "instead of inertial-missing on every link."},
      {kProductsSignSuspect, Severity::kWarning, true,
       "The products of inertia have the wrong sign: the inertia is invalid as written but valid "
       "with them negated, or the geometry's products have the opposite sign."},
      {kUnitsSuspect, Severity::kWarning, true,
       "The radius of gyration is out of proportion with the link's geometry (unit mistake)."},
      {kInertiaAboutOriginSuspect, Severity::kWarning, true,
       "The inertia looks like it is about the link origin rather than the center of mass."},
      {kInertiaExceedsGeometry, Severity::kWarning, true,
       "No mass distribution inside the link's geometry bounding box has this inertia."},
      {kComOutsideGeometry, Severity::kWarning, true,
       "The center of mass is outside the bounding box of the link's geometry."},
      {kInertiaNearBoundary, Severity::kNote, true,
       "The inertia is physically valid only within the tolerance."},
      {kUrdfNotLoadable, Severity::kError, true,
       "urdfdom (ROS's URDF parser) refuses the file; its mass properties are checked from a "
       "lenient reading."},
      {kInertialUnreadable, Severity::kError, true,
       "A number of a link's <inertial> cannot be read; the other links are still checked."},
      {kIncludeUnresolved, Severity::kWarning, true,
       "An SDF <include> cannot be resolved; the rest of the file is still checked."},
      {"inertial-auto", Severity::kNote, true,
       "An SDF 1.11 <inertial auto=\"true\"> was computed from the link's collisions."},
  };
  // The geometry rules (geometry_checks.h) run only with --geometry; listed here so that every
  // rule id is known to the tool, the configuration file and SARIF.
  static const std::vector<RuleInfo> kAll = [] {
    std::vector<RuleInfo> all = kRules;
    all.insert(all.end(), DensityRules().begin(), DensityRules().end());  // density_rules.h
    all.insert(all.end(), TargetRules().begin(), TargetRules().end());    // --target (issue 16)
    all.insert(all.end(), GeometryRules().begin(), GeometryRules().end());
    return all;
  }();
  return kAll;
}

std::vector<Finding> CheckModel(const Model& model, const CheckOptions& options) {
  std::vector<Finding> findings = Checker(model, options).Run();
  AddDensityFindings(model, options, &findings);  // density_rules.h
  return findings;
}

std::vector<Finding> ReaderFindings(const ReadResult& read, const CheckOptions& options) {
  std::vector<Finding> findings;
  for (const ReadFinding& rf : read.findings) {
    std::optional<Severity> severity;
    const auto it = options.overrides.find(rf.rule);
    if (it != options.overrides.end()) {
      severity = it->second;
    } else {
      for (const RuleInfo& info : AllRules()) {
        if (info.id == rf.rule && info.enabled_by_default) severity = info.default_severity;
      }
    }
    if (!severity) continue;
    bool ignored = false;
    for (const Model& model : read.models) {
      if (!rf.model.empty() && model.name != rf.model) continue;
      const int index = rf.link.empty() ? -1 : model.FindLink(rf.link);
      if (index < 0) continue;
      for (const std::string& rule : model.links[index].ignored_rules) {
        ignored = ignored || rule == "all" || rule == rf.rule;
      }
    }
    if (ignored) continue;
    Finding f;
    f.rule = rf.rule;
    f.severity = *severity;
    f.model = rf.model;
    f.link = rf.link;
    f.location = rf.location;
    f.message = rf.message;
    f.values = rf.values;
    findings.push_back(std::move(f));
  }
  return findings;
}

std::optional<LinkShape> CalcLinkShape(const Link& link, const LinkShapeFunction& fallback) {
  for (const bool collision : {true, false}) {
    const std::optional<GeometryBounds> bounds = BoundsOf(link, collision);
    if (!bounds) continue;
    Link primitives;  // only the chosen set, so that CalcPrimitiveMassProperties uses it
    for (const Geometry& g : link.geometries) {
      if (g.is_collision == collision) primitives.geometries.push_back(g);
    }
    const std::optional<PrimitiveMassProperties> unit =
        CalcPrimitiveMassProperties(primitives, /*density=*/1, /*mass=*/1);
    if (!unit) continue;
    LinkShape shape;
    shape.from_collision = collision;
    shape.box_B = bounds->box_B;
    shape.volume = unit->volume;
    shape.p_BoBcm_B = unit->p_BoBcm_B;
    shape.G_BBcm_B = unit->I_BBcm_B;
    shape.kind = "primitive";
    return shape;
  }
  if (!fallback) return std::nullopt;
  try {
    return fallback(link);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::optional<ProductsSignEvidence> FindProductsSignEvidence(const Inertial& in,
                                                             const LinkShape& shape) {
  const double m = in.mass;
  if (!(m > 0) || !std::isfinite(m)) return std::nullopt;
  const Eigen::Matrix3d I = WrittenMatrix(in);
  const Eigen::Matrix3d& R = in.X_BBi.R_AB;
  const Eigen::Matrix3d G = m * (R.transpose() * shape.G_BBcm_B * R);  // in Bi
  if (!I.allFinite() || !G.allFinite()) return std::nullopt;
  const Eigen::Vector3d p_written(I(0, 1), I(0, 2), I(1, 2));
  const Eigen::Vector3d p_geometry(G(0, 1), G(0, 2), G(1, 2));
  const double mean_geometry = G.trace() / 3;
  const double mean_written = I.trace() / 3;
  // Products of at least 10% of the mean moment on both sides: smaller ones are within what a
  // simplified geometry or a non-uniform density can change, and say nothing about the sign.
  if (!(mean_geometry > 0) || !(mean_written > 0)) return std::nullopt;
  if (p_geometry.norm() < 0.1 * mean_geometry || p_written.norm() < 0.1 * mean_written) {
    return std::nullopt;
  }
  // The geometry must describe the body: every moment within a factor 2.
  for (int i = 0; i < 3; ++i) {
    const double d = I(i, i), g = G(i, i);
    if (!(d > 0) || !(g > 0) || std::max(d / g, g / d) > 2) return std::nullopt;
  }
  // The direction of the products is what a uniform-density model gets right; their size less
  // so (a motor inside a shell): the written products must point within about 25° of the
  // opposite of the geometry's (cosine <= -0.9) and be within a factor 2 of their size.
  const double size_ratio = p_written.norm() / p_geometry.norm();
  const double cosine = p_written.dot(p_geometry) / (p_written.norm() * p_geometry.norm());
  if (!(cosine <= -0.9) || size_ratio > 2 || size_ratio < 0.5) return std::nullopt;
  ProductsSignEvidence evidence;
  evidence.geometry_products = p_geometry;
  evidence.cosine = cosine;
  evidence.mismatch_as_written = (p_written - p_geometry).norm() / p_geometry.norm();
  evidence.mismatch_negated = (p_written + p_geometry).norm() / p_geometry.norm();
  return evidence;
}

std::optional<GeometryBounds> CalcLinkGeometryBounds(const Link& link) {
  bool has_collision = false, has_visual = false;
  for (const Geometry& g : link.geometries) (g.is_collision ? has_collision : has_visual) = true;
  std::optional<GeometryBounds> collision = BoundsOf(link, /*collision=*/true);
  std::optional<GeometryBounds> visual = BoundsOf(link, /*collision=*/false);
  // Collision geometry often covers only part of the body while the visual covers all of it:
  // the union of both, marked partial when one of them is not all primitives.
  if (collision && visual) {
    collision->box_B.extend(visual->box_B);
    collision->count += visual->count;
    return collision;
  }
  if (collision) {
    collision->partial = has_visual;
    return collision;
  }
  if (visual) visual->partial = has_collision;
  return visual;
}

std::optional<GeometryBounds> CalcLinkGeometryBounds(const Link& link,
                                                     const std::optional<LinkShape>& shape) {
  std::optional<GeometryBounds> bounds = CalcLinkGeometryBounds(link);
  if (bounds && !bounds->partial) return bounds;
  // A shape from the same primitives adds nothing; a mesh shape fills in what is not known.
  if (!shape || (bounds && shape->kind != "mesh")) return bounds;
  GeometryBounds from_shape{shape->box_B, shape->from_collision, 1, shape->kind == "mesh", false};
  if (bounds) from_shape.box_B.extend(bounds->box_B);
  return from_shape;
}

std::optional<GeometryBounds> CalcLinkGeometryBounds(const Link& link,
                                                     const std::optional<LinkShape>& shape,
                                                     const LinkBoxFunction& box) {
  std::optional<GeometryBounds> bounds = CalcLinkGeometryBounds(link, shape);
  if ((bounds && !bounds->partial) || !box) return bounds;
  std::optional<LinkGeometryBox> read;
  try {
    read = box(link);
  } catch (const std::exception&) {
    return bounds;
  }
  if (!read || read->known == 0 || read->box_B.isEmpty()) return bounds;
  GeometryBounds result;
  result.box_B = read->box_B;
  result.from_collision = read->from_collision;
  result.count = read->known;
  result.from_mesh = read->meshes > 0;
  result.partial = read->unknown > 0;
  return result;
}

}  // namespace massprops
