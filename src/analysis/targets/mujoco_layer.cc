// --target mujoco: the findings PredictMujoco's refusals give (CheckMujoco), what physics says
// about each, the compiler option that accepts the file, and what MuJoCo decides about each
// inertia physics refuses (AnnotateMujoco).
#include "analysis/targets/target_layer.h"

namespace massprops::targets {
namespace {

// What physics says about MuJoCo's refusal, and which compiler option accepts the file.
std::string ExplainMujocoError(const Model& model, const MujocoError& e, const MujocoBody* body,
                               double tolerance) {
  const Link* link = e.link >= 0 ? &model.links[e.link] : nullptr;
  std::string text;
  if (e.rule == kMujocoTriangle) {
    const std::array<double, 3>& m = e.inertia;
    text = "its principal moments, as MuJoCo's eigen-solver computes them, are " + Moments(m) +
           ": " + Num(m[1]) + " + " + Num(m[2]) + " < " + Num(m[0]) +
           " (MuJoCo's test is exact, "
           "without tolerance). ";
    if (link && link->inertial && PhysicallyValid(WrittenMatrixOf(*link->inertial), tolerance)) {
      text += "Physics disagrees: the inertia is valid within " + Num(tolerance) +
              " of its trace (a thin shape written with rounded numbers). ";
    } else {
      text += "Physics agrees: no real body has this inertia. ";
    }
    const double mean = (m[0] + m[1] + m[2]) / 3;
    text +=
        "Accepted with <mujoco><compiler balanceinertia=\"true\"/></mujoco> (all three "
        "moments become their mean " +
        Num(mean) + "), or after `massprops fix --target mujoco` (the nearest valid inertia)";
  } else if (e.rule == kMujocoMinValRule) {
    const std::array<double, 3>& m = e.inertia;
    text = "after fusing static bodies its mass is " + Num(e.mass) + " and its principal moments " +
           Moments(m) + " (mjMINVAL = 1e-15, an absolute bound). ";
    if (e.mass < kMujocoMinVal) {
      text +=
          "Physics agrees when nothing with mass moves with it; a massless intermediate link "
          "of a multi-axis joint is fine in physics (Drake accepts it), not in MuJoCo. ";
    } else {
      text +=
          "Physics disagrees: a principal moment of 0 is a valid thin rod or point mass "
          "(MuJoCo's floor is absolute, not relative to the body's size). ";
    }
    text +=
        "Accepted with <mujoco><compiler boundmass=\"1e-6\" boundinertia=\"1e-9\"/></mujoco> "
        "(raises every body below them)";
    if (link && HasCollision(*link)) {
      text +=
          ", or inertiafromgeom=\"true\" (every body's inertia from its collision geoms, the "
          "written ones ignored)";
    }
    text += ", or after `massprops fix --target mujoco` (a negligible mass and moment floor)";
  } else if (e.rule == kMujocoFusedInertia) {
    text =
        "fusing the links welded to it by fixed joints (fusestatic, on for URDF) gives the "
        "principal moments " +
        Moments(e.inertia) + ", the smallest below 1e-14";
    if (body != nullptr && !body->fused_links.empty()) {
      text += " (fused: ";
      for (std::size_t i = 0; i < body->fused_links.size(); ++i) {
        text += (i ? ", '" : "'") + model.links[body->fused_links[i]].name + "'";
      }
      text += ")";
    }
    text +=
        "; MuJoCo names no body in its message. Accepted with <mujoco><compiler "
        "fusestatic=\"false\"/></mujoco>, or after `massprops fix --target mujoco`";
  } else if (e.rule == kMujocoGeomMass) {
    text =
        "the link has no <inertial>, so MuJoCo takes its inertia from its geoms (density 1000, "
        "visual geoms 0), which give mass " +
        Num(e.mass) + "; add an <inertial>, or run `massprops fix --target mujoco`";
  } else {
    text = "mass " + Num(e.mass) + ", principal moments " + Moments(e.inertia) +
           " after boundmass/boundinertia";
  }
  return text;
}

}  // namespace

void CheckMujoco(const Model& model, const CheckOptions& options,
                 const MujocoCompilerOptions& mujoco, FindingSink* sink) {
  const MujocoPrediction prediction = PredictMujoco(model, mujoco);
  for (const std::string& why : prediction.unsupported) {
    sink->Emit(kMujocoUnpredicted, -1, model.location,
               "MuJoCo's decision cannot be fully predicted: " + why, {});
  }
  for (std::size_t i = 0; i < prediction.errors.size(); ++i) {
    const MujocoError& e = prediction.errors[i];
    const MujocoBody* body = nullptr;
    for (const MujocoBody& b : prediction.bodies) {
      if (b.link == e.link) body = &b;
    }
    const Link* link = e.link >= 0 ? &model.links[e.link] : nullptr;
    std::string message = "MuJoCo 2.2.2 refuses the file" +
                          std::string(link ? " at body '" + link->name + "'" : "") + ": \"" +
                          e.message + "\"" +
                          (i == 0 ? " (the first refusal: this is the one MuJoCo reports)" : "") +
                          "; " + ExplainMujocoError(model, e, body, options.tolerance);
    sink->Emit(e.rule, e.link, link ? InertiaLocationOf(*link) : model.location, std::move(message),
               {{"mass", e.mass},
                {"principal_1", e.inertia[0]},
                {"principal_2", e.inertia[1]},
                {"principal_3", e.inertia[2]},
                {"first", i == 0 ? 1.0 : 0.0}});
  }
}

void AnnotateMujoco(const Model& model, const MujocoCompilerOptions& mujoco,
                    std::vector<Finding>* findings) {
  // Say what MuJoCo decides about each inertia physics refuses.
  const MujocoPrediction prediction = PredictMujoco(model, mujoco);
  for (Finding& f : *findings) {
    if (f.rule != "inertia-not-physical") continue;
    const int index = model.FindLink(f.link);
    if (index < 0 || !model.links[index].inertial) continue;
    bool refused = false;
    for (const MujocoError& e : prediction.errors) refused |= e.link == index;
    if (f.message.find("composite inertia") != std::string::npos) {
      f.message += " (MuJoCo judges each link on its own before fusing, not the group)";
    } else if (refused) {
      f.message += " (MuJoCo refuses it too: see the mujoco-rejects finding)";
    } else {
      const Inertial& in = *model.links[index].inertial;
      const MujocoEigen eig = MujocoEig3({in.ixx, in.iyy, in.izz, in.ixy, in.ixz, in.iyz});
      f.message += " (MuJoCo 2.2.2 accepts it: its eigen-solver gives the principal moments " +
                   Moments(eig.values) +
                   ", negative ones clamped to 0, which pass its test; physics and MuJoCo "
                   "disagree)";
    }
  }
}

}  // namespace massprops::targets
