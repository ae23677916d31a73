// units-suspect (warning): the radius of gyration is out of proportion with the link's size.
//
// Evidence: the written inertia and mass (the radius of gyration k = sqrt(tr(I)/(2m))); the size
// of the link's geometry (the half-diagonal of its bounding box, collision and visual; for "too
// large" that of its welded group's known geometry); where the geometry gives no size (none,
// placeholder geometry, a mesh not read), the kinematic tree (the joints around the link, its
// center of mass, its welded group's geometry); for a placeholder or dummy link, its welded
// group's central inertia.
// Why: a solid body filling its box has k ≈ 0.45–0.58 times the box's half-diagonal. A kg·mm²
// inertia makes k sqrt(1e6) = 1000 times too large, a mass in grams sqrt(1000) = 31.6 times too
// small: flagged beyond kUnitsRatio either way. The message lists the causes that fit (a unit
// slip, a placeholder, a mass edited without its inertia) and what the numbers say of each. A
// link with nothing to judge it by is flagged when its typed-in isotropic inertia is at least
// kMadeUpInertiaShare of its welded group's (CheckMadeUpInertia).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "analysis/rules/kinematic_chain.h"
#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kUnitsSuspect = "units-suspect";

// units-suspect: the radius of gyration k = sqrt(tr(I)/(2m)) is flagged when k / (half-diagonal
// of the geometry's bounding box) is above kUnitsRatio or below 1/kUnitsRatio (a kg·mm² inertia
// makes k sqrt(1e6) = 1000 times too large, a mass in grams makes it sqrt(1000) = 31.6 times too
// small), or, without known geometry, when k exceeds kMaxGyrationRadiusWithoutGeometry.
constexpr double kUnitsRatio = 30;
constexpr double kMaxGyrationRadiusWithoutGeometry = 10;  // metres
// units-suspect by the kinematic tree (a link whose geometry does not give its size): a radius of
// gyration beyond this many times the span from the link's origin to its farthest joint, center
// of mass and welded geometry (a rod spanning it has k = span/sqrt(12) about its center, at most
// span about the origin; a body several times larger than every joint around it is no link's);
// larger when some of the group's geometry is of unknown size.
constexpr double kKinematicRatio = 5;
constexpr double kKinematicRatioPartial = 8;

// A unit mistake and the factor by which it makes (k / k_expected)² too large.
// `cause` and `help` are its words in a headline and a help line.
struct UnitSlip {
  double factor;
  const char* text;
  const char* cause;
  const char* help;
};
constexpr UnitSlip kUnitSlips[] = {
    {1e6, "the inertia looks like kg·mm² (1e6 too large): multiply it by 1e-6", "in kg·mm²?",
     "multiply the inertia by 1e-6 (massprops fix --apply units-suspect does it)"},
    {1e4, "the inertia looks like kg·cm² (1e4 too large): multiply it by 1e-4", "in kg·cm²?",
     "multiply the inertia by 1e-4 (massprops fix --apply units-suspect does it)"},
    {1e-3, "the mass looks like grams (1000 too large): divide it by 1000", "mass in grams?",
     "divide the mass by 1000 (massprops fix --apply units-suspect does it)"},
    {1e-6, "the inertia looks 1e6 too small (converted from kg·mm² twice?)", "1e6 too small?",
     "multiply the inertia by 1e6 (massprops fix --apply units-suspect does it)"},
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

// The likely cause in a few words for a headline, and the help that goes with it.
struct CauseWords {
  std::string cause;
  std::string help;
};

// CauseWords from what the numbers say: a unit slip (`slip`, when `slip_fits`), a placeholder,
// both, or neither (as Verdict).
CauseWords WordsFor(const UnitSlip& slip, bool slip_fits, bool placeholder) {
  if (slip_fits && placeholder) {
    return {"units or placeholder?",
            "compare with the part's CAD (massprops explain units-suspect lists the causes)"};
  }
  if (slip_fits) return {slip.cause, slip.help};
  if (placeholder) {
    return {"placeholder?",
            "write the part's inertia (from CAD, or massprops fix --from-geometry)"};
  }
  return {"mass or inertia edited?",
          "write one part's mass and inertia from CAD (massprops explain units-suspect)"};
}

// The words of Causes(I, m, ratio, extent) for a headline.
CauseWords LikelyCause(const Eigen::Matrix3d& I, double ratio) {
  const double factor = ratio * ratio / 0.25;
  const UnitSlip& slip = NearestUnitSlip(factor);
  const double fixed_ratio = ratio / std::sqrt(slip.factor);
  return WordsFor(slip, fixed_ratio >= 0.3 && fixed_ratio <= 1, !PlaceholderPattern(I).empty());
}

// "inertia 1.03e6x too large" / "inertia 1e3x too small": the factor (k / k_expected)² by which
// the inertia misses that of a solid filling its box (k_expected = half the half-diagonal).
std::string InertiaFactorWords(double ratio) {
  const double factor = ratio * ratio / 0.25;
  return factor >= 1 ? "inertia " + FormatRatio(factor) + " too large"
                     : "inertia " + FormatRatio(1 / factor) + " too small";
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

// The size the kinematic tree gives a link whose geometry does not (none, placeholder geometry,
// a mesh of unknown size): its body reaches from its parent joint (its origin) to its child
// joints and its center of mass, and over the known geometry of its welded group; a leaf (no
// child joint) is judged by its parent's span too (a fingertip is not larger than the phalanx
// it hangs from; an inertial link welded to a base is not larger than the base's joints).
struct KinematicScale {
  double span = 0;       // metres, from the link origin
  std::string evidence;  // what gave it
  bool partial = false;  // some geometry of the group (or the link's own) has unknown size
};

KinematicScale KinematicScaleOf(const RuleContext& ctx, int link_index, const Eigen::Vector3d& c) {
  KinematicScale scale;
  // The joints outboard of it, up to two joints away (a two-axis joint's intermediate link has
  // its child joint at its own origin; the body it moves reaches to the next joint).
  double joints = 0;
  for (const auto& [child, j] : ctx.children[link_index]) {
    const Pose& X_LC = ctx.model.joints[j].X_PC;
    joints = std::max(joints, X_LC.p_AB.norm());
    for (const auto& [grandchild, k] : ctx.children[child]) {
      (void)grandchild;
      joints = std::max(joints, (X_LC * ctx.model.joints[k].X_PC).p_AB.norm());
    }
  }
  double parent_span = 0;
  const int parent = ctx.parent[link_index];
  if (ctx.children[link_index].empty() && parent >= 0) {
    for (const auto& [child, j] : ctx.children[parent]) {
      (void)child;
      parent_span = std::max(parent_span, ctx.model.joints[j].X_PC.p_AB.norm());
    }
  }
  // The known geometry of the welded group, as far as it reaches from this link's origin.
  double group_reach = 0;
  const Link& link = ctx.model.links[link_index];
  scale.partial = !link.geometries.empty() && !ctx.BoundsOfLink(link_index);
  // The farthest corner of the group's boxes from the link's origin, both in the root's frame
  // (the group's corners indexed once per group: every member of a welded group asks).
  const RuleContext::GroupCorners& group = ctx.GroupCornersOf(ctx.group_of[link_index]);
  scale.partial = scale.partial || group.partial;
  group_reach = group.corners_R.MaxDistance(ctx.GroupPoseOf(link_index).p_AB);
  // A link with no joint at all (a single free body) has no kinematic tree to give it a size.
  if (ctx.children[link_index].empty() && parent < 0) return scale;
  const double com = c.norm();
  scale.span = std::max({joints, parent_span, group_reach, com});
  scale.evidence = "farthest joint outboard (two joints deep) " + Num(joints) +
                   " m, center of mass " + Num(com) + " m" +
                   (parent_span > 0 ? ", the parent's farthest joint " + Num(parent_span) + " m"
                                    : std::string()) +
                   (group_reach > 0 ? ", its welded group's geometry " + Num(group_reach) + " m"
                                    : std::string());
  // Joints at one point (a compound hip's links between coincident axes), or a span far below
  // the chain around the link: no evidence; the limb the link belongs to is (kinematic_chain.h).
  const ChainSpan chain = ChainSpanOf(ctx, link_index);
  if (scale.span <= kCoincidentLength || kFarBelowChain * scale.span < chain.span) {
    if (chain.span > scale.span) {
      scale.span = chain.span;
      scale.evidence += "; its own span is no evidence, so " + chain.evidence;
    }
  }
  return scale;
}

// units-suspect for a link whose size its geometry does not give (no geometry, placeholder
// geometry, a mesh of unknown size): k beyond kKinematicRatio times the span the kinematic tree
// gives it (KinematicScaleOf) — a body reaches at least k from its center of mass, and a link
// does not reach far beyond its joints and its welded group. Where some geometry of the group is
// of unknown size the body may be larger: kKinematicRatioPartial. Dummy masses (<= kDummyMass)
// are left to CheckMadeUpInertia.
bool CheckUnitsAgainstKinematics(RuleContext& ctx, const JudgedLink& judged, double k) {
  const Link& link = *judged.link;
  const double m = link.inertial->mass;
  if (!(m > kDummyMass)) return false;
  // Its own geometry of unknown size (a mesh not read) may be the body: the mesh, once read,
  // judges it (a hand's phalanges drawn by meshes), not the joints.
  if (!link.geometries.empty() && !ctx.BoundsOfLink(judged.index)) return false;
  if (const std::optional<GeometryBounds>& own = ctx.BoundsOfLink(judged.index);
      own && own->partial) {
    return false;
  }
  const KinematicScale scale = KinematicScaleOf(ctx, judged.index, judged.props.p_FoScm_F);
  if (!(scale.span > kCoincidentLength)) return false;  // no length to divide by
  const double limit = scale.partial ? kKinematicRatioPartial : kKinematicRatio;
  const double ratio = k / scale.span;
  if (!(ratio > limit)) return false;
  const std::string because =
      judged.unjudged_because.empty()
          ? (link.geometries.empty() ? "the link has no geometry"
                                     : "its geometry's size is unknown (a mesh not read)")
          : judged.unjudged_because;
  const CauseWords words = LikelyCause(judged.I_written, ratio);
  ctx.Emit(
      kUnitsSuspect, link, InertiaLocation(link),
      judged.who + ": radius of gyration sqrt(tr(I)/(2m)) = " + Num(k) + " m is " + Num(ratio) +
          " times the " + Num(scale.span) + " m its kinematic tree gives it (" + scale.evidence +
          "; " + because + "; expected at most " + Num(limit) +
          "): " + Causes(judged.I_written, m, ratio, scale.span),
      {{"radius_of_gyration", k},
       {"kinematic_span", scale.span},
       {"ratio", ratio},
       {"mass", m},
       {"trace", judged.I_written.trace()}},
      LinkHeadline(link.name, ": radius of gyration " + FormatLength(k) + " is " +
                                  FormatRatio(ratio) + " the " + FormatLength(scale.span) +
                                  " span of its joints (" + words.cause + ")"),
      {{"radius_of_gyration_m", k}, {"joint_span_m", scale.span}, {"ratio", ratio}, {"mass_kg", m}},
      words.help);
  return true;
}

}  // namespace

const RuleInfo& UnitsSuspectRule() {
  static const RuleInfo kInfo{
      kUnitsSuspect, Severity::kWarning, true,
      "The radius of gyration is out of proportion with the link's geometry (unit mistake)."};
  return kInfo;
}

bool CheckUnits(RuleContext& ctx, const JudgedLink& judged) {
  const Link& link = *judged.link;
  const double m = link.inertial->mass;
  const double trace = judged.I_written.trace();
  if (!(trace > 0)) return false;
  const double k = std::sqrt(trace / (2 * m));
  if (!judged.bounds) {
    if (CheckUnitsAgainstKinematics(ctx, judged, k)) return true;
    // A dummy mass (<= kDummyMass) with a typed-in floor inertia (1e-6 kg·m² on 1e-8 kg
    // control surfaces) is no body whose size matters: its inertia is judged by what it does to
    // its welded group (CheckMadeUpInertia). One whose inertia has a CAD export's digits is a
    // part whose mass was edited without its inertia: still judged.
    if (!(k > kMaxGyrationRadiusWithoutGeometry)) return false;
    if (!(m > kDummyMass) && !PlaceholderPattern(judged.I_written).empty()) return false;
    const CauseWords no_geometry =
        WordsFor(kUnitSlips[0], k / 1000 <= 1, !PlaceholderPattern(judged.I_written).empty());
    ctx.Emit(kUnitsSuspect, link, InertiaLocation(link),
             judged.who + ": radius of gyration sqrt(tr(I)/(2m)) = " + Num(k) + " m is beyond " +
                 Num(kMaxGyrationRadiusWithoutGeometry) +
                 " m (the link has no geometry of known size): " +
                 CausesWithoutGeometry(judged.I_written, k),
             {{"radius_of_gyration", k}, {"mass", m}, {"trace", trace}},
             LinkHeadline(link.name, ": radius of gyration " + FormatLength(k) +
                                         ", over 10 m, no geometry (" + no_geometry.cause + ")"),
             {{"radius_of_gyration_m", k}, {"mass_kg", m}, {"trace_kg_m2", trace}},
             no_geometry.help);
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
  const CauseWords words = LikelyCause(judged.I_written, ratio);
  ctx.Emit(
      kUnitsSuspect, link, InertiaLocation(link),
      judged.who + ": radius of gyration sqrt(tr(I)/(2m)) = " + Num(k) + " m is " + Num(ratio) +
          " times the half-diagonal " + Num(extent) + " m of its " + judged.geometry_name +
          " geometry (expected " + "about 0.3 to 1): " +
          Causes(judged.I_written, m, ratio, extent) + MeshScaleHint(*judged.bounds, ratio),
      {{"radius_of_gyration", k},
       {"geometry_half_diagonal", extent},
       {"ratio", ratio},
       {"mass", m},
       {"trace", trace}},
      LinkHeadline(link.name,
                   ": " + InertiaFactorWords(ratio) + " for its size (" + words.cause +
                       (MeshScaleHint(*judged.bounds, ratio).empty() ? "" : " or mesh in mm?") +
                       ")"),
      {{"radius_of_gyration_m", k}, {"half_diagonal_m", extent}, {"ratio", ratio}, {"mass_kg", m}},
      words.help);
  return true;
}

// units-suspect for a link the ratio test cannot judge (placeholder geometry, a dummy mass):
// such links are left alone because they do not matter, which holds only if their inertia does
// not either. Flags a typed-in isotropic inertia (PlaceholderPattern) that is at least
// kMadeUpInertiaShare of its welded group's central inertia (the group has other members with
// mass): numbers no body backs that change the group's dynamics (pr2's 1 g accelerometers with
// I = 1e-3 kg·m², 8% of the gripper palm group; 0.1 kg cameras with I = 0.01 kg·m²).
bool CheckMadeUpInertia(RuleContext& ctx, const JudgedLink& judged) {
  if (judged.bounds || judged.unjudged_because.empty()) return false;
  const std::string pattern = BlanketPlaceholder(judged.I_written);
  if (pattern.empty()) return false;
  const Link& link = *judged.link;
  const WeldedGroup& group = ctx.groups[ctx.group_of[judged.index]];
  if (group.links.size() < 2) return false;
  const CompositeInertia& composite = ctx.GroupComposite(ctx.group_of[judged.index]);
  const double total = composite.I_SScm_R.trace();
  if (!(composite.mass > link.inertial->mass) || !(total > 0)) return false;
  // The made-up inertias of a group add up: judge their sum (pr2's head carries eleven frames
  // with I = 1e-3 or 1e-2 kg·m², each a few percent of the head, together three times its own).
  double made_up = 0;
  int others = 0;
  for (int i : group.links) {
    const Link& member = ctx.model.links[i];
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
  ctx.Emit(kUnitsSuspect, link, InertiaLocation(link),
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
            {"other_links", others}},
           LinkHeadline(link.name,
                        ": typed-in inertia " + FormatSignificant(judged.I_written(0, 0)) + " is " +
                            FormatSignificant(100 * share) + "% of that of its welded group"),
           {{"radius_of_gyration_m", k},
            {"mass_kg", m},
            {"trace_kg_m2", own},
            {"share_of_welded_group_percent", 100 * share},
            {"other_links_count", static_cast<double>(others)}},
           "give the link its part's inertia, or zero if it is only a frame");
  return true;
}

}  // namespace rules
}  // namespace massprops
