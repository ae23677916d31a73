// model-without-inertials (note): no link of an SDF model has an <inertial>.
//
// Evidence: every link of the model (none has an <inertial>, none is unreadable), the format
// (SDF), and the first link with collision geometry (where the note points).
// Why: such a model is a kinematic or visual description (sdformat's and gz-sim's frame and pose
// test models): SDFormat gives each link mass 1 kg and inertia diag(1, 1, 1) kg·m², fine unless
// it is simulated. One note for the model instead of inertial-missing on every link.

#include <string>

#include "analysis/rules/rules.h"

namespace massprops {
namespace rules {
namespace {

constexpr const char* kModelWithoutInertials = "model-without-inertials";

}  // namespace

const RuleInfo& ModelWithoutInertialsRule() {
  static const RuleInfo kInfo{
      kModelWithoutInertials, Severity::kNote, true,
      "No link of an SDF model has an <inertial> (a kinematic or visual model): said once, "
      "instead of inertial-missing on every link."};
  return kInfo;
}

void NoteModelWithoutInertials(RuleContext& ctx, const WeldedGroup& group) {
  if (ctx.model_note_given) return;
  for (int i : group.links) {
    const Link& link = ctx.model.links[i];
    bool collision = false;
    for (const Geometry& g : link.geometries) collision = collision || g.is_collision;
    if (!collision) continue;
    ctx.model_note_given = true;
    const double links = static_cast<double>(ctx.model.links.size());
    ctx.Emit(kModelWithoutInertials, link, link.location,
             "no link of model '" + ctx.model.name +
                 "' has an <inertial>: SDFormat gives each of its " +
                 std::to_string(ctx.model.links.size()) +
                 " link(s) the default mass 1 kg and inertia diag(1, 1, 1) kg·m²; fine for a "
                 "kinematic or visual model, wrong for a robot that is simulated",
             {{"links", links}},
             ModelHeadline(ctx.model.name, " has no <inertial>: SDF gives its " +
                                               std::to_string(ctx.model.links.size()) +
                                               " link(s) 1 kg each"),
             {{"links_count", links}},
             "fine for a visual model; for simulation add <inertial>s (massprops fix "
             "--from-geometry)");
    return;
  }
}

}  // namespace rules
}  // namespace massprops
