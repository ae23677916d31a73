#include "massprops/analysis/repair.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "analysis/repair_judge.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/finding_text.h"
#include "massprops/analysis/fix_text.h"
#include "massprops/analysis/welded_groups.h"
#include "massprops/core/format_number.h"
#include "massprops/core/principal_axes.h"
#include "massprops/core/rotational_inertia.h"
#include "massprops/core/unit_inertia.h"

namespace massprops {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Below this radius of gyration (m) a body's inertia is not projected (see Planner::Project).
constexpr double kMinRadiusOfGyration = 1e-4;

Eigen::Matrix3d WrittenMatrix(const Inertial& in) {
  Eigen::Matrix3d I;
  I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  return I;
}

void SetMatrix(const Eigen::Matrix3d& I, Inertial* in) {
  in->ixx = I(0, 0);
  in->iyy = I(1, 1);
  in->izz = I(2, 2);
  // The matrix is symmetric up to round-off; write the mean of the two triangles.
  in->ixy = 0.5 * (I(0, 1) + I(1, 0));
  in->ixz = 0.5 * (I(0, 2) + I(2, 0));
  in->iyz = 0.5 * (I(1, 2) + I(2, 1));
  // Negative zero would be written "-0".
  for (double* x : {&in->ixx, &in->iyy, &in->izz, &in->ixy, &in->ixz, &in->iyz}) {
    if (*x == 0) *x = 0;
  }
}

bool IsValid(const Eigen::Matrix3d& I, double tolerance) {
  return internal::IsPhysicallyValidInertia(I(0, 0), I(1, 1), I(2, 2), I(1, 0), I(2, 0), I(2, 1),
                                            tolerance);
}

// The Euclidean projection of λ onto {λ : σ_i(λ) >= floor, i = 1..3} (a convex polyhedral cone
// shifted by the floor). The projection lies on the affine set of its active constraints: try all
// 8 subsets, project onto each affine set, keep the nearest feasible candidate.
Eigen::Vector3d ProjectMoments(const Eigen::Vector3d& lambda, double floor) {
  Eigen::Matrix3d A;  // rows a_i
  for (int i = 0; i < 3; ++i) {
    A.row(i).setConstant(0.5);
    A(i, i) = -0.5;
  }
  const double slack = 1e-6 * floor;
  Eigen::Vector3d best = lambda;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int mask = 0; mask < 8; ++mask) {
    std::vector<int> active;
    for (int i = 0; i < 3; ++i) {
      if (mask & (1 << i)) active.push_back(i);
    }
    Eigen::Vector3d candidate = lambda;
    if (!active.empty()) {
      const int k = static_cast<int>(active.size());
      Eigen::MatrixXd A_S(k, 3);
      for (int r = 0; r < k; ++r) A_S.row(r) = A.row(active[r]);
      const Eigen::VectorXd residual = Eigen::VectorXd::Constant(k, floor) - A_S * lambda;
      const Eigen::MatrixXd gram = A_S * A_S.transpose();
      const Eigen::VectorXd mu = gram.ldlt().solve(residual);
      candidate = lambda + A_S.transpose() * mu;
    }
    if ((A * candidate).minCoeff() < floor - slack) continue;
    const double distance = (candidate - lambda).squaredNorm();
    if (distance < best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  return best;
}

double Volume(const Geometry& g) {
  switch (g.type) {
    case Geometry::Type::kBox:
      return g.size.prod();
    case Geometry::Type::kCylinder:
      return kPi * g.radius * g.radius * g.length;
    case Geometry::Type::kSphere:
      return 4.0 / 3.0 * kPi * std::pow(g.radius, 3);
    case Geometry::Type::kCapsule:
      return kPi * g.radius * g.radius * g.length + 4.0 / 3.0 * kPi * std::pow(g.radius, 3);
    case Geometry::Type::kEllipsoid:
      return 4.0 / 3.0 * kPi * g.radii.prod();
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

// The unit inertia of the solid about its center, in its own frame G.
std::optional<Eigen::Matrix3d> UnitInertiaOf(const Geometry& g) {
  auto ok = [](double x) { return std::isfinite(x) && x >= 0; };
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  switch (g.type) {
    case Geometry::Type::kBox:
      if (!ok(g.size.x()) || !ok(g.size.y()) || !ok(g.size.z())) return std::nullopt;
      return UnitInertia<double>::SolidBox(g.size.x(), g.size.y(), g.size.z()).CopyToFullMatrix3();
    case Geometry::Type::kCylinder:
      if (!ok(g.radius) || !ok(g.length)) return std::nullopt;
      return UnitInertia<double>::SolidCylinder(g.radius, g.length, z).CopyToFullMatrix3();
    case Geometry::Type::kSphere:
      if (!ok(g.radius)) return std::nullopt;
      return UnitInertia<double>::SolidSphere(g.radius).CopyToFullMatrix3();
    case Geometry::Type::kCapsule:
      if (!ok(g.radius) || !ok(g.length)) return std::nullopt;
      return UnitInertia<double>::SolidCapsule(g.radius, g.length, z).CopyToFullMatrix3();
    case Geometry::Type::kEllipsoid:
      if (!ok(g.radii.x()) || !ok(g.radii.y()) || !ok(g.radii.z())) return std::nullopt;
      return UnitInertia<double>::SolidEllipsoid(g.radii.x(), g.radii.y(), g.radii.z())
          .CopyToFullMatrix3();
    default:
      return std::nullopt;
  }
}

std::optional<PrimitiveMassProperties> FromGeometries(const Link& link, bool collision,
                                                      double density, double mass) {
  std::vector<MassProperties> parts;
  Eigen::Matrix3d G_first_B = Eigen::Matrix3d::Zero();  // unit inertia of the first part, in B
  double volume = 0;
  for (const Geometry& g : link.geometries) {
    if (g.is_collision != collision) continue;
    const std::optional<Eigen::Matrix3d> G = UnitInertiaOf(g);
    const double v = Volume(g);
    if (!G || !std::isfinite(v) || !g.X_BG.p_AB.allFinite() || !g.X_BG.R_AB.allFinite()) {
      return std::nullopt;
    }
    MassProperties part;
    part.mass = v;  // Unit density first; scaled below.
    part.p_FoScm_F = g.X_BG.p_AB;
    const Eigen::Matrix3d G_B = g.X_BG.R_AB * *G * g.X_BG.R_AB.transpose();
    part.I_SScm_F = v * G_B;
    if (parts.empty()) G_first_B = G_B;
    parts.push_back(part);
    volume += v;
  }
  if (parts.empty() || !(volume > 0) || !std::isfinite(volume)) return std::nullopt;
  CompositeInertia composite;
  if (parts.size() == 1) {  // Exact: no division of v·p by v.
    composite.mass = parts[0].mass;
    composite.p_RoScm_R = parts[0].p_FoScm_F;
    composite.I_SScm_R = parts[0].I_SScm_F;
  } else {
    composite = ComposeMassProperties(parts);
  }
  PrimitiveMassProperties result;
  result.volume = volume;
  result.mass = mass > 0 ? mass : density * volume;
  result.p_BoBcm_B = composite.p_RoScm_R;
  // One part: m·G exactly (no round trip through the volume).
  result.I_BBcm_B =
      parts.size() == 1 ? result.mass * G_first_B : (result.mass / volume) * composite.I_SScm_R;
  result.from_collision = collision;
  if (!result.I_BBcm_B.allFinite() || !result.p_BoBcm_B.allFinite()) return std::nullopt;
  return result;
}

// Fills repair->changes and relative_change from repair->before (the link's inertial) and after.
void RecomputeChanges(const Model& model, const Link& link, Repair* repair) {
  repair->changes.clear();
  repair->inserts_origin = false;
  const bool sdf = model.format == Model::Format::kSdf;
  if (link.inertial) {
    const Inertial& b = *link.inertial;
    const Inertial& a = repair->after;
    auto add = [&](const char* element, const char* attribute, int line, int first,
                   std::vector<double> old_values, std::vector<double> new_values) {
      if (old_values == new_values) return;
      repair->changes.push_back(
          {element, attribute, line, first, std::move(old_values), std::move(new_values)});
    };
    add("mass", sdf ? "" : "value", b.mass_location.line, 0, {b.mass}, {a.mass});
    if (b.X_BBi.p_AB != a.X_BBi.p_AB) {
      if (b.pose_location.line == 0) repair->inserts_origin = true;
      add(sdf ? "pose" : "origin", sdf ? "" : "xyz", b.pose_location.line, 0,
          {b.X_BBi.p_AB.x(), b.X_BBi.p_AB.y(), b.X_BBi.p_AB.z()},
          {a.X_BBi.p_AB.x(), a.X_BBi.p_AB.y(), a.X_BBi.p_AB.z()});
    }
    const int line = b.inertia_location.line;
    add("inertia", "ixx", line, 0, {b.ixx}, {a.ixx});
    add("inertia", "ixy", line, 0, {b.ixy}, {a.ixy});
    add("inertia", "ixz", line, 0, {b.ixz}, {a.ixz});
    add("inertia", "iyy", line, 0, {b.iyy}, {a.iyy});
    add("inertia", "iyz", line, 0, {b.iyz}, {a.iyz});
    add("inertia", "izz", line, 0, {b.izz}, {a.izz});
    const Eigen::Matrix3d R = b.X_BBi.R_AB;
    const Eigen::Matrix3d I_before = R * WrittenMatrix(b) * R.transpose();
    const Eigen::Matrix3d I_after = R * WrittenMatrix(a) * R.transpose();
    if (I_before.norm() > 0 && I_before != I_after) {
      repair->relative_change = (I_after - I_before).norm() / I_before.norm();
    } else if (I_before == I_after && b.mass != 0) {
      repair->relative_change = std::abs(a.mass - b.mass) / std::abs(b.mass);
    } else {
      repair->relative_change = 1;
    }
  } else {
    repair->relative_change = 1;
  }
}

// A number written into the file: the shortest decimal that reads back to the same double.
std::string Num(double x) { return FormatShortest(x); }

// A number in a sentence of the why text: 6 significant digits, enough to recognise it.
std::string Short(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.6g", x);
  return buffer;
}

std::string Percent(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.3g%%", 100 * x);
  return buffer;
}

// A repair being built for one link: the working inertial and the steps taken.
struct Plan {
  Inertial work;
  std::vector<std::string> methods;
  std::vector<std::string> whys;
  std::string rule;
  bool inserts_inertial = false;
  std::set<std::string> targets;  // the rules of the link this plan answers
};

class Planner {
 public:
  Planner(const Model& model, const RepairOptions& options) : model_(model), options_(options) {}

  // Refusals found while planning (a heuristic asked for that has no candidate that fits).
  std::vector<RefusedRepair> refused;

  // Whether the heuristic repair of `rule` was asked for (RepairOptions::apply).
  bool Allows(const std::string& rule) const {
    if (rule == "units-suspect" && options_.fix_units) return true;
    for (const std::string& a : options_.apply) {
      if (a == rule || a == "all") return true;
    }
    return false;
  }

  std::optional<Repair> PlanLink(const Link& link, const std::set<std::string>& rules) {
    Plan plan;
    const bool named =
        std::find(options_.from_geometry_links.begin(), options_.from_geometry_links.end(),
                  link.name) != options_.from_geometry_links.end();
    if (options_.from_geometry_all || named) {
      if (FromGeometry(link, /*keep_mass=*/true, rules.empty() ? "" : *rules.begin(), &plan)) {
        return Finish(link, plan);
      }
    }
    if (!link.inertial) {
      if (rules.count("massless-moving-body") && Allows("massless-moving-body") &&
          HasCollision(link) &&
          FromGeometry(link, /*keep_mass=*/false, "massless-moving-body", &plan)) {
        return Finish(link, plan);
      }
      if (rules.count("inertial-missing") && Allows("inertial-missing") &&
          FromGeometry(link, /*keep_mass=*/false, "inertial-missing", &plan)) {
        return Finish(link, plan);
      }
      return std::nullopt;
    }
    const Inertial& in = *link.inertial;
    if (rules.count("massless-moving-body") && Allows("massless-moving-body") && in.mass == 0 &&
        HasCollision(link)) {
      if (FromGeometry(link, /*keep_mass=*/false, "massless-moving-body", &plan)) {
        return Finish(link, plan);
      }
    }
    if (rules.count("mass-not-positive")) {
      if (Allows("mass-not-positive") &&
          FromGeometry(link, /*keep_mass=*/false, "mass-not-positive", &plan)) {
        return Finish(link, plan);
      }
      return std::nullopt;
    }
    if (!WrittenMatrix(in).allFinite() || !std::isfinite(in.mass)) return std::nullopt;
    plan.work = in;
    if (rules.count("units-suspect") && Allows("units-suspect")) RescaleUnits(link, &plan);
    if (rules.count("inertia-about-origin-suspect") && Allows("inertia-about-origin-suspect")) {
      ShiftToCom(&plan);
    }
    if (rules.count("products-sign-suspect") && Allows("products-sign-suspect")) {
      NegateProducts(link, &plan);
    }
    // Projection answers inertia-not-physical: only for a link that has that finding (not one
    // whose finding the file ignores or the configuration turns off: `fix` never changes a link
    // that has no error), or whose heuristic repair above left an invalid inertia.
    const bool reported = rules.count("inertia-not-physical") > 0;
    if ((reported || !plan.methods.empty()) &&
        !IsValid(WrittenMatrix(plan.work), options_.tolerance)) {
      Project(link, &plan);
    }
    if (plan.methods.empty()) return std::nullopt;
    return Finish(link, plan);
  }

 private:
  static bool HasCollision(const Link& link) {
    for (const Geometry& g : link.geometries) {
      if (g.is_collision) return true;
    }
    return false;
  }

  // The inertial frame's rotation R_BBi of the link (identity without inertial).
  static Eigen::Matrix3d RotationOf(const Link& link) {
    return link.inertial ? link.inertial->X_BBi.R_AB : Eigen::Matrix3d::Identity();
  }

  // CalcLinkShape with options_.shape, once per link (a mesh shape reads and integrates meshes).
  const std::optional<LinkShape>& ShapeOf(const Link& link) const {
    auto it = shapes_.find(link.name);
    if (it == shapes_.end())
      it = shapes_.emplace(link.name, CalcLinkShape(link, options_.shape)).first;
    return it->second;
  }

  // The link's geometry as a uniform solid of `mass` (> 0), else of density·volume: its
  // primitives, else options_.shape (meshes). *kind: "primitive" or "mesh".
  std::optional<PrimitiveMassProperties> GeometryOf(const Link& link, double mass,
                                                    std::string* kind) const {
    *kind = "primitive";
    if (std::optional<PrimitiveMassProperties> g =
            CalcPrimitiveMassProperties(link, options_.density, mass)) {
      return g;
    }
    if (!options_.shape || !(options_.density > 0) || !std::isfinite(options_.density)) {
      return std::nullopt;
    }
    const std::optional<LinkShape>& shape = ShapeOf(link);
    if (!shape) return std::nullopt;
    PrimitiveMassProperties g;
    g.volume = shape->volume;
    g.mass = mass > 0 ? mass : options_.density * shape->volume;
    g.p_BoBcm_B = shape->p_BoBcm_B;
    g.I_BBcm_B = g.mass * shape->G_BBcm_B;
    // A mesh's 32-bit vertices leave products of about 1e-19 where the true value is 0; below
    // 1e-9 of the trace (far under the vertices' 6e-8 rounding) a product is written as 0.
    const double noise = 1e-9 * std::abs(g.I_BBcm_B.trace());
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        if (i != j && std::abs(g.I_BBcm_B(i, j)) <= noise) g.I_BBcm_B(i, j) = 0;
      }
    }
    g.from_collision = shape->from_collision;
    *kind = shape->kind;
    if (!(g.mass > 0) || !std::isfinite(g.mass) || !g.I_BBcm_B.allFinite()) return std::nullopt;
    return g;
  }

  bool FromGeometry(const Link& link, bool keep_mass, const std::string& rule, Plan* plan) {
    const double mass = link.inertial ? link.inertial->mass : 0;
    const bool use_mass = keep_mass && std::isfinite(mass) && mass > 0;
    std::string kind;
    std::optional<PrimitiveMassProperties> g = GeometryOf(link, use_mass ? mass : 0, &kind);
    if (!g) return false;
    Inertial work = link.inertial ? *link.inertial : Inertial{};
    const Eigen::Matrix3d R = RotationOf(link);
    work.mass = g->mass;
    work.X_BBi.p_AB = g->p_BoBcm_B;
    SetMatrix(R.transpose() * g->I_BBcm_B * R, &work);
    plan->work = work;
    plan->rule = rule.empty() ? "--from-geometry" : rule;
    if (!rule.empty()) plan->targets.insert(rule);
    plan->inserts_inertial = !link.inertial.has_value();
    const std::string what =
        std::string(g->from_collision ? "collision" : "visual") + (kind == "mesh" ? " mesh" : "");
    const std::string adjective = kind == "mesh" ? "" : "primitive ";
    if (use_mass) {
      plan->methods.push_back("from-geometry");
      plan->whys.push_back("the inertia (and center of mass) of the link's " + adjective + what +
                           " geometry, solid and uniform, with the link's mass " + Short(mass) +
                           " kg");
    } else {
      plan->methods.push_back("from-geometry-density");
      std::string reason =
          rule == "massless-moving-body" ? "the link moves but its body has no mass"
          : !link.inertial               ? "the link has " + what + " geometry but no <inertial>"
                                         : "the mass " + Short(mass) + " is not a positive number";
      plan->whys.push_back(reason + ": mass = density " + Short(options_.density) +
                           " kg/m³ × volume " + Short(g->volume) + " m³ = " + Short(g->mass) +
                           " kg, with the inertia and center of mass of its " + adjective + what +
                           " geometry (solid, uniform)");
    }
    return true;
  }

  void Note(Plan* plan, const char* rule, const char* method, std::string why) {
    if (plan->rule.empty()) plan->rule = rule;
    plan->targets.insert(rule);
    plan->methods.push_back(method);
    plan->whys.push_back(std::move(why));
  }

  void RescaleUnits(const Link& link, Plan* plan) {
    Inertial& w = plan->work;
    const Eigen::Matrix3d I = WrittenMatrix(w);
    const double trace = I.trace();
    if (!(w.mass > 0) || !(trace > 0)) return;
    const std::optional<GeometryBounds> bounds =
        CalcLinkGeometryBounds(link, ShapeOf(link), options_.box);
    const bool mesh = bounds && bounds->from_mesh;
    const double extent = bounds ? 0.5 * bounds->box_B.diagonal().norm() : 0;
    struct Candidate {
      double inertia_factor;
      double mass_factor;
      const char* text;
    };
    static const Candidate kCandidates[] = {
        {1e-6, 1, "the inertia taken as kg·mm²: multiplied by 1e-6"},
        {1e-4, 1, "the inertia taken as kg·cm²: multiplied by 1e-4"},
        {1, 1e-3, "the mass taken as grams: divided by 1000"},
        {1e6, 1, "the inertia was 1e6 too small: multiplied by 1e6"},
    };
    // A solid body inside its geometry has k between about 0.3 and 0.6 of the half-diagonal e; a
    // candidate is plausible when its k/e lands in [0.1, 2] (2: the checks' allowance for
    // simplified geometry). Without geometry, only the kg·mm² reading is considered (k > 10 m).
    std::vector<std::pair<double, const Candidate*>> plausible;  // (|log(ratio/0.5)|, candidate)
    const Candidate* nearest = nullptr;
    double nearest_score = std::numeric_limits<double>::infinity();
    for (const Candidate& c : kCandidates) {
      const double k_new = std::sqrt(trace * c.inertia_factor / (2 * w.mass * c.mass_factor));
      if (extent > 0) {
        const double ratio = k_new / extent;
        const double score = std::abs(std::log(ratio / 0.5));
        // Against a mesh, "the inertia is 1e6 too small" is indistinguishable from "the mesh is
        // in millimetres without a scale", the commoner mistake: never chosen on its own then.
        const bool ambiguous = mesh && c.inertia_factor == 1e6;
        if (ratio >= 0.1 && ratio <= 2 && !ambiguous) plausible.push_back({score, &c});
        if (ratio > 1.0 / 30 && ratio < 30 && score < nearest_score) {
          nearest_score = score;
          nearest = &c;
        }
      } else if (c.inertia_factor == 1e-6 && k_new <= 10) {
        nearest = &c;
      }
    }
    const Candidate* chosen = nullptr;
    if (extent > 0 && plausible.size() == 1) {
      chosen = plausible.front().second;
    } else if (options_.fix_units) {
      chosen = nearest;
    }
    if (chosen == nullptr) {
      const double k = std::sqrt(trace / (2 * w.mass));
      std::string why = "inertia trace " + Short(trace) + " kg·m² on a " + Short(w.mass) +
                        " kg body: radius of gyration " + Short(k) + " m";
      if (extent > 0 && plausible.size() > 1) {
        why += "; more than one unit factor fits the geometry (half-diagonal " + Short(extent) +
               " m), so which one is a guess (--fix-units takes the nearest)";
      } else if (extent > 0) {
        why += " against a geometry half-diagonal of " + Short(extent) +
               " m; no unit factor (inertia ×1e-6, ×1e-4, ×1e6, mass ÷1000) makes it fit";
      } else {
        why += "; the link has no geometry to tell which unit factor, if any, fits";
      }
      why +=
          "; the causes that fit these numbers: a placeholder inertia, a mass edited without its "
          "inertia, values raised on purpose to stabilise a simulation, or a unit slip — not "
          "repaired; compare the link's mass and inertia with its CAD model";
      RefusedRepair refusal{"units-suspect", link.name, link.location.line, why, "", {}, {}};
      refusal.reason = extent > 0 && plausible.size() > 1
                           ? "more than one unit factor fits its size"
                       : extent > 0 ? "no unit factor makes its inertia fit its size"
                                    : "it has no geometry to tell which unit factor fits";
      refusal.evidence.push_back("radius of gyration " + FormatLength(k) + " on a " +
                                 FormatMass(w.mass) + " body" +
                                 (extent > 0 ? ", half diagonal " + FormatLength(extent) : ""));
      refusal.evidence.push_back(
          "a placeholder, a mass edited without its inertia, values raised for a simulator's "
          "stability, or a unit slip: the numbers alone do not tell which");
      refused.push_back(std::move(refusal));
      return;
    }
    w.mass *= chosen->mass_factor;
    SetMatrix(I * chosen->inertia_factor, &w);
    Note(plan, "units-suspect", "rescale-units",
         std::string(
             "the radius of gyration was out of proportion with the geometry and this is the one "
             "unit factor that makes the link fit it (asked for by --apply units-suspect); ") +
             chosen->text);
  }

  void ShiftToCom(Plan* plan) {
    Inertial& w = plan->work;
    const Eigen::Matrix3d& R = w.X_BBi.R_AB;
    const Eigen::Vector3d& c = w.X_BBi.p_AB;
    const Eigen::Matrix3d I_B = R * WrittenMatrix(w) * R.transpose();
    const Eigen::Matrix3d I_shifted =
        I_B - w.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
    if (!IsValid(I_shifted, options_.tolerance)) return;
    SetMatrix(R.transpose() * I_shifted * R, &w);
    Note(plan, "inertia-about-origin-suspect", "shift-to-com",
         "the numbers were the inertia about the link origin: shifted to the center of mass " +
             std::string("(") + Short(c.x()) + ", " + Short(c.y()) + ", " + Short(c.z()) +
             ") by subtracting m·(|c|²·1 − c·cᵀ)");
  }

  void NegateProducts(const Link& link, Plan* plan) {
    Inertial& w = plan->work;
    Eigen::Matrix3d I = WrittenMatrix(w);
    Eigen::Matrix3d negated = -I;
    negated.diagonal() = I.diagonal();
    if (!IsValid(negated, options_.tolerance)) return;
    if (IsValid(I, options_.tolerance)) {
      // Valid both ways: negate only on the geometry's evidence (as the check judged it).
      const std::optional<LinkShape>& shape = ShapeOf(link);
      if (!shape) return;
      const std::optional<ProductsSignEvidence> evidence = FindProductsSignEvidence(w, *shape);
      if (!evidence) return;
      SetMatrix(negated, &w);
      Note(plan, "products-sign-suspect", "negate-products",
           "the products of inertia had the opposite sign of those the link's geometry implies "
           "(+∫xy dm instead of −∫xy dm): negated ixy, ixz, iyz, which then match the "
           "geometry's to " +
               Percent(evidence->mismatch_negated));
      return;
    }
    // Where the link has geometry, negate only when that lands closer to the geometry's
    // inertia (with the link's mass, in the inertial frame) than the projection does.
    if (w.mass > 0) {
      std::string kind;
      if (std::optional<PrimitiveMassProperties> g = GeometryOf(link, w.mass, &kind)) {
        const Eigen::Matrix3d& R = w.X_BBi.R_AB;
        const Eigen::Matrix3d I_geometry = R.transpose() * g->I_BBcm_B * R;
        const Eigen::Matrix3d projected = RepairInertia(I, options_.method, options_.tolerance);
        if ((negated - I_geometry).norm() > (projected - I_geometry).norm()) return;
      }
    }
    SetMatrix(negated, &w);
    Note(plan, "products-sign-suspect", "negate-products",
         "the products of inertia had the wrong sign convention (+∫xy dm instead of −∫xy dm): "
         "negated ixy, ixz, iyz, which alone makes the inertia valid");
  }

  void Project(const Link& link, Plan* plan) {
    Inertial& w = plan->work;
    const Eigen::Matrix3d I = WrittenMatrix(w);
    const Eigen::Matrix3d repaired = RepairInertia(I, options_.method, options_.tolerance);
    // A body whose radius of gyration is below 0.1 mm (a 1 kg body with moments under 1e-8
    // kg·m²) has no inertia worth projecting: the numbers are a units or placeholder mistake,
    // and a projection would hide it behind a valid-looking tensor of the same nonsense size.
    const double k = w.mass > 0 ? std::sqrt(std::abs(repaired.trace()) / (2 * w.mass)) : 0;
    if (w.mass > 0 && k < kMinRadiusOfGyration) {
      RefusedRepair refusal{"inertia-not-physical", link.name, link.location.line, "", "", {}, {}};
      refusal.why = "inertia of trace " + Short(I.trace()) + " kg·m² on a " + Short(w.mass) +
                    " kg body: radius of gyration " + Short(k) +
                    " m; a units or placeholder mistake, not a rounding error — not repaired";
      refusal.reason = "its inertia is far too small for its mass to be a rounding error";
      refusal.evidence.push_back("inertia trace " + FormatInertia(I.trace()) + " on a " +
                                 FormatMass(w.mass) + " body: radius of gyration " +
                                 FormatLength(k) + " (below 0.1 mm)");
      refusal.evidence.push_back(
          "a units or placeholder mistake, not a rounding error: a projection would hide it");
      refused.push_back(std::move(refusal));
      return;
    }
    SetMatrix(repaired, &w);
    const double change = I.norm() > 0 ? (repaired - I).norm() / I.norm() : 1;
    const Eigen::Vector3d before = internal::ScaledPrincipalMoments(
        I(0, 0), I(1, 1), I(2, 2), I(1, 0), I(2, 0), I(2, 1), PrincipalSolver::kAccurate);
    const Eigen::Vector3d after = internal::ScaledPrincipalMoments(
        repaired(0, 0), repaired(1, 1), repaired(2, 2), repaired(1, 0), repaired(2, 0),
        repaired(2, 1), PrincipalSolver::kAccurate);
    const std::string moments = "principal moments " + Short(before(0)) + ", " + Short(before(1)) +
                                ", " + Short(before(2)) + " → " + Short(after(0)) + ", " +
                                Short(after(1)) + ", " + Short(after(2));
    if (options_.method == InertiaRepairMethod::kBalance) {
      Note(plan, "inertia-not-physical", "balance",
           "no mass distribution has this inertia: all three principal moments set to their mean "
           "(MuJoCo's balanceinertia); " +
               moments + " (relative change " + Percent(change) + ")");
    } else {
      Note(plan, "inertia-not-physical", "project",
           "no mass distribution has this inertia: replaced by the nearest valid inertia with "
           "the same principal axes; " +
               moments + " (relative change " + Percent(change) + ")");
    }
  }

  Repair Finish(const Link& link, const Plan& plan) {
    Repair repair;
    repair.rule = plan.rule;
    repair.link = link.name;
    repair.link_line = link.location.line;
    for (std::size_t i = 0; i < plan.methods.size(); ++i) {
      repair.method += (i ? "+" : "") + plan.methods[i];
      repair.why += (i ? "; then " : "") + plan.whys[i];
    }
    if (!repair.why.empty()) repair.why += ".";
    repair.before = link.inertial;
    repair.after = plan.work;
    repair.inserts_inertial = plan.inserts_inertial;
    RecomputeChanges(model_, link, &repair);
    repair.answers.assign(plan.targets.begin(), plan.targets.end());
    return repair;
  }

  const Model& model_;
  const RepairOptions& options_;
  mutable std::map<std::string, std::optional<LinkShape>> shapes_;  // ShapeOf's memo
};

}  // namespace

std::optional<PrimitiveMassProperties> CalcPrimitiveMassProperties(const Link& link, double density,
                                                                   double mass) {
  if (!(density > 0) || !std::isfinite(density)) return std::nullopt;
  bool has_collision = false;
  for (const Geometry& g : link.geometries) has_collision |= g.is_collision;
  return FromGeometries(link, has_collision, density, mass);
}

void FillRepairChanges(const Model& model, const Link& link, Repair* repair) {
  RecomputeChanges(model, link, repair);
}

const std::vector<std::string>& HeuristicRepairRules() {
  static const std::vector<std::string> kRules = {
      "units-suspect",     "products-sign-suspect", "inertia-about-origin-suspect",
      "mass-not-positive", "massless-moving-body",  "inertial-missing"};
  return kRules;
}

Eigen::Matrix3d RepairInertia(const Eigen::Matrix3d& I, InertiaRepairMethod method,
                              double tolerance) {
  if (!I.allFinite() || IsValid(I, tolerance)) return I;
  const auto [lambda, V] = CalcSymmetricEigensystem<double>(I, PrincipalSolver::kAccurate);
  if (method == InertiaRepairMethod::kBalance) {
    double mean = lambda.sum() / 3;
    if (!(mean > 0)) mean = lambda.cwiseAbs().sum() / 3;
    return mean * Eigen::Matrix3d::Identity();
  }
  const double floor = kValidityFloor * lambda.cwiseAbs().maxCoeff();
  const Eigen::Vector3d projected = ProjectMoments(lambda, floor);
  Eigen::Matrix3d result = V * projected.asDiagonal() * V.transpose();
  result = 0.5 * (result + result.transpose()).eval();
  return result;
}

namespace {

using internal::RulesOfLinks;

// The rules of the findings on each link. massless-moving-body is reported once per group (or
// once per kinematics-only model, with the value "moving_groups"): every member link of the
// massless moving group(s) gets it, so that each may get a mass.
RulesOfLinks FindRulesOfLinks(const Model& model, const std::vector<Finding>& findings) {
  RulesOfLinks rules_of;
  for (const Finding& f : findings) {
    if (!f.link.empty()) rules_of[f.link].insert(f.rule);
  }
  bool massless_found = false;
  for (const Finding& f : findings) massless_found |= f.rule == "massless-moving-body";
  if (!massless_found) return rules_of;
  const std::vector<WeldedGroup> groups = FindWeldedGroups(model);
  for (const Finding& f : findings) {
    if (f.rule != "massless-moving-body") continue;
    bool whole_model = false;
    for (const auto& [name, value] : f.values) whole_model |= name == "moving_groups";
    for (const WeldedGroup& group : groups) {
      if (!group.is_moving || (!whole_model && group.root_link != f.link)) continue;
      for (int i : group.links) rules_of[model.links[i].name].insert(f.rule);
    }
  }
  return rules_of;
}

// The repairs the planner proposes, in file order (those that change something); the repairs it
// refuses are added to `refused` when given.
std::vector<Repair> PlanEachLink(const Model& model, const RepairOptions& options,
                                 const RulesOfLinks& rules_of,
                                 std::vector<RefusedRepair>* refused) {
  Planner planner(model, options);
  std::vector<Repair> planned;
  for (const Link& link : model.links) {
    const auto it = rules_of.find(link.name);
    static const std::set<std::string> kNone;
    const std::set<std::string>& rules = it == rules_of.end() ? kNone : it->second;
    std::optional<Repair> repair = planner.PlanLink(link, rules);
    if (!repair) continue;
    if (repair->changes.empty() && !repair->inserts_inertial) continue;
    planned.push_back(std::move(*repair));
  }
  if (refused) refused->insert(refused->end(), planner.refused.begin(), planner.refused.end());
  return planned;
}

}  // namespace

std::vector<Repair> PlanRepairs(const Model& model, const std::vector<Finding>& findings,
                                const RepairOptions& options, std::vector<RefusedRepair>* refused) {
  const RulesOfLinks rules_of = FindRulesOfLinks(model, findings);
  std::vector<Repair> repairs = PlanEachLink(model, options, rules_of, refused);
  if (repairs.empty()) return repairs;
  const internal::RepairJudge judge(model, options);
  internal::DropFailingRepairs(judge, &repairs, refused);
  internal::RoundRepairs(model, judge, &repairs);
  if (repairs.empty()) return repairs;
  internal::FindResolved(model, judge.check_options(), rules_of, &repairs);
  return repairs;
}

void AttachRepairs(const std::vector<Repair>& repairs, std::vector<Finding>& findings) {
  for (Finding& f : findings) {
    for (const Repair& r : repairs) {
      if (r.link == f.link &&
          std::find(r.resolves.begin(), r.resolves.end(), f.rule) != r.resolves.end()) {
        f.repair = r;
        break;
      }
    }
  }
}

Model ApplyRepairs(const Model& model, const std::vector<Repair>& repairs) {
  Model repaired = model;
  for (const Repair& r : repairs) {
    const int i = repaired.FindLink(r.link);
    if (i < 0) continue;
    Inertial after = r.after;
    if (repaired.links[i].inertial) {
      const Inertial& before = *repaired.links[i].inertial;
      after.location = before.location;
      after.mass_location = before.mass_location;
      after.inertia_location = before.inertia_location;
      after.pose_location = before.pose_location;
    } else {
      after.location = repaired.links[i].location;
    }
    repaired.links[i].inertial = after;
  }
  return repaired;
}

std::string DescribeRepair(const Repair& repair) {
  std::string text = "link '" + repair.link + "' [" + repair.rule + " → " + repair.method + "]";
  if (repair.inserts_inertial) {
    const Inertial& a = repair.after;
    text += ": new <inertial>\n  mass " + Num(a.mass) + ", center of mass (" +
            Num(a.X_BBi.p_AB.x()) + ", " + Num(a.X_BBi.p_AB.y()) + ", " + Num(a.X_BBi.p_AB.z()) +
            ")\n  inertia ixx " + Num(a.ixx) + ", iyy " + Num(a.iyy) + ", izz " + Num(a.izz) +
            "\n  inertia ixy " + Num(a.ixy) + ", ixz " + Num(a.ixz) + ", iyz " + Num(a.iyz);
  }
  for (const FieldChange& c : repair.changes) {
    auto join = [](const std::vector<double>& v) {
      std::string s;
      for (std::size_t i = 0; i < v.size(); ++i) s += (i ? " " : "") + Num(v[i]);
      return s;
    };
    text += "\n  " + c.element + (c.attribute.empty() ? "" : " " + c.attribute);
    if (c.line > 0) text += " (line " + std::to_string(c.line) + ")";
    text += ": " + join(c.old_values) + " → " + join(c.new_values);
  }
  const std::vector<std::string> why = WrapWords(repair.why, kMaxDetailChars - 7);
  for (std::size_t i = 0; i < why.size(); ++i) text += (i ? "\n       " : "\n  why: ") + why[i];
  text += "\n  relative change: " + Percent(repair.relative_change);
  return text;
}

}  // namespace massprops
