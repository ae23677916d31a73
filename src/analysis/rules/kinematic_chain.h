#pragma once
// The span of the joint chain around a link (private to src/analysis/rules/): what gives a link
// a size when its own joints do not (issue 34). A humanoid's compound hip or ankle puts two or
// three joints at one point; the geometry-less links between them have a span (the distance
// between their joints) of zero within round-off (5.6e-17 m), which is no evidence of their size:
// the body they belong to is the limb, from the nearest joint inboard that is not at that point
// to the nearest outboard one, with the geometry of the links there.

#include <string>

#include "analysis/rules/rule_context.h"

namespace massprops {
namespace rules {

// Joints closer than this are at one point for judging a body's size: joints written at one
// point (5.6e-17 m after a composition of rotations) or a CAD export's sub-millimetre offsets
// between the axes of a compound joint; a part whose inertia matters is larger.
constexpr double kCoincidentLength = 1e-3;  // metres
// A link's own span (its joints two deep, its center of mass, its welded geometry) this many
// times below the span of the chain around it is no evidence of its size either.
constexpr double kFarBelowChain = 100;

// The chain around link `link_index`, measured from its origin: walking inboard (parent links)
// and outboard (child links, every branch) through every joint that lies at the link's origin
// (within kCoincidentLength), up to the first joint that does not; and the known geometry of the
// links that span from the point to those joints (the links hung at the point, the parent whose
// joint ends the walk inboard).
struct ChainSpan {
  double inboard = 0;   // metres: the nearest inboard joint (or link origin) not at the origin
  double outboard = 0;  // metres: the farthest, over the branches, of each branch's nearest one
  double geometry = 0;  // metres: how far the known geometry of those links reaches
  double span = 0;      // the largest of the three
  int links = 0;        // links walked through at the origin (the degenerate chain's members)
  std::string evidence;
};
ChainSpan ChainSpanOf(const RuleContext& ctx, int link_index);

// How far the known geometry of link `n`, posed at X_LN in the frame of a link L, reaches from
// L's origin (0 without geometry); sets *partial when some of it is of unknown size.
double GeometryReach(const RuleContext& ctx, int n, const Pose& X_LN, bool* partial = nullptr);

}  // namespace rules
}  // namespace massprops
