// inertial-missing (warning): a link has collision geometry but no <inertial>.
//
// Evidence: the link's collision geometry (its size, and its volume as primitives), its welded
// group (the masses of its members, does it move, is it welded to the world), the model's format
// (SDF gives a link without <inertial> mass 1, URDF makes it massless) and whether the group has
// mass outboard of it (the massless-link-with-mass-outboard note).
// Why: a body has mass; a link with a body and no <inertial> has forgotten it, unless its mass is
// lumped on welded neighbours (a modelling choice). The collision volume at the lightest density
// a solid part has (kMinBodyDensity) tells a body the group's mass cannot be.
//
// inertial-missing: a link with a body (collision geometry of real size) and no <inertial>
// where nothing else carries its mass. A link welded to members that carry mass is a modelling
// choice, not a forgotten mass: the body's mass is lumped on them (a root whose mass sits on an
// `inertial_link`, collision-helper links, accessory plates, connectors whose inertials were
// commented out), unless the link's own collision volume would weigh more than the whole group
// even at kMinBodyDensity. A URDF link whose group has no mass is judged only when the group
// moves with mass outboard of it (`mass_outboard`: the massless-link-with-mass-outboard note):
// a body on a joint that has no mass of its own. The root group of a URDF (fixed to the world or
// a floating base: the file does not say) and a group welded to the world (in MJCF, every group
// that does not move: it is welded to the <worldbody>) never move, so their mass never matters;
// where the group's zero mass makes the mass matrix singular, the error massless-moving-body says
// it.

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kInertialMissing = "inertial-missing";

// The lightest density of a solid part: rigid foams (expanded polystyrene, polyurethane) are about
// 15 to 100 kg/m³ (Ashby, Materials Selection in Mechanical Design, 4th ed., chart 4.3: foams
// span 10 to 1000 kg/m³ and nothing structural is lighter); a part lighter than 50 kg/m³ over its
// collision volume is a foam block at most.
constexpr double kMinBodyDensity = 50;  // kg/m³

// Whether a joint whose parent is not a link of the model (SDF "world") holds `group` with a
// fixed joint: then nothing in it ever moves, and its mass never enters the dynamics.
bool WeldedToWorld(const RuleContext& ctx, const WeldedGroup& group) {
  if (group.is_moving) return false;
  for (int i : group.links) {
    if (ctx.welded_to_world[i]) return true;
  }
  return false;
}

}  // namespace

const RuleInfo& InertialMissingRule() {
  static const RuleInfo kInfo{kInertialMissing, Severity::kWarning, true,
                              "A link has collision geometry but no <inertial>."};
  return kInfo;
}

void CheckInertialMissing(RuleContext& ctx, const WeldedGroup& group, bool mass_outboard) {
  // An SDF model none of whose links has an <inertial> is a kinematic or visual description
  // (sdformat's and gz-sim's frame and pose test models): one note for the model, not a warning
  // per link.
  if (ctx.sdf_without_inertials) {
    NoteModelWithoutInertials(ctx, group);
    return;
  }
  if (WeldedToWorld(ctx, group)) return;
  // MJCF: the <worldbody> is the root link "world"; a group that does not move is welded to it
  // (its floor and static scenery): its mass never enters the dynamics.
  if (ctx.model.format == Model::Format::kMjcf && !group.is_moving) return;
  double group_mass = 0;
  for (int i : group.links) {
    const Link& link = ctx.model.links[i];
    if (link.inertial && std::isfinite(link.inertial->mass) && link.inertial->mass > 0) {
      group_mass += link.inertial->mass;
    }
  }
  const bool urdf = ctx.model.format == Model::Format::kUrdf;
  if (urdf && group_mass == 0 && !mass_outboard) return;
  for (int i : group.links) {
    const Link& link = ctx.model.links[i];
    if (link.inertial) continue;
    int collisions = 0;
    for (const Geometry& g : link.geometries) collisions += g.is_collision ? 1 : 0;
    if (collisions == 0) continue;
    // Zero-size or 1 mm placeholder collisions on a frame link: nothing to give a mass to.
    const std::optional<GeometryBounds>& b = ctx.BoundsOfLink(i);
    if (b && !b->partial && 0.5 * b->box_B.diagonal().norm() < kPlaceholderHalfDiagonal) {
      continue;
    }
    std::string evidence;
    std::vector<std::pair<std::string, double>> values = {{"collisions", collisions},
                                                          {"group_mass", group_mass}};
    if (group_mass > 0) {
      // The mass is lumped on a welded neighbour, unless this link's collision primitives
      // alone, at the lightest density a solid part has, outweigh the whole group.
      const std::optional<LinkShape> solid = CalcLinkShape(link);
      if (!solid || !solid->from_collision) continue;
      const double floor_mass = kMinBodyDensity * solid->volume;
      if (!(floor_mass > group_mass)) continue;
      evidence = "; its welded group carries only " + Num(group_mass) +
                 " kg, while its collision volume " + Num(solid->volume) + " m³ would weigh " +
                 Num(floor_mass) + " kg even at " + Num(kMinBodyDensity) +
                 " kg/m³ (the lightest foams): the group's mass cannot be this body's";
      values.emplace_back("collision_volume", solid->volume);
      values.emplace_back("mass_at_min_density", floor_mass);
    } else if (urdf) {
      evidence =
          "; it moves on a joint with mass outboard of it, and nothing welded to it has "
          "mass";
    }
    std::vector<std::pair<std::string, double>> parts = {{"collision_shapes_count", collisions},
                                                         {"group_mass_kg", group_mass}};
    for (const auto& [name, value] : values) {
      if (name == "collision_volume") parts.emplace_back("collision_volume_m3", value);
      if (name == "mass_at_min_density") parts.emplace_back("mass_at_min_density_kg", value);
    }
    ctx.Emit(
        kInertialMissing, link, link.location,
        "link '" + link.name + "' has " + std::to_string(collisions) + " collision geometr" +
            (collisions == 1 ? "y" : "ies") +
            " but no <inertial>: its mass was probably forgotten (" +
            (ctx.model.format == Model::Format::kSdf
                 ? "SDF gives it the default mass 1 kg and inertia diag(1, 1, 1) kg·m²)"
                 : "URDF makes it massless)") +
            evidence,
        std::move(values),
        LinkHeadline(link.name, " has collision geometry but no <inertial> (mass forgotten?)"),
        std::move(parts),
        "add an <inertial> from CAD, or massprops fix --apply inertial-missing (from geometry)");
  }
}

}  // namespace rules
}  // namespace massprops
