#include "massprops/analysis/mass_repair.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "massprops/analysis/welded_groups.h"

namespace massprops {
namespace {

// x rounded to kMassRepairDigits significant digits (0 and non-finite values as they are).
double Round(double x) {
  if (x == 0 || !std::isfinite(x)) return x;
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*e", kMassRepairDigits - 1, x);
  return std::strtod(buffer, nullptr);
}

// A number in a sentence: 6 significant digits.
std::string Short(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.6g", x);
  return buffer;
}

// The inertial with its six inertia numbers multiplied by k and rounded (a 0 stays 0; the
// products are scaled as written, so their sign convention does not matter).
void ScaleInertia(double k, Inertial* in) {
  for (double* x : {&in->ixx, &in->iyy, &in->izz, &in->ixy, &in->ixz, &in->iyz}) {
    *x = Round(*x * k);
    if (*x == 0) *x = 0;  // never "-0"
  }
}

Repair MakeRepair(const Model& model, const Link& link, const std::string& rule,
                  const std::string& method, const Inertial& after, std::string why) {
  Repair r;
  r.rule = rule;
  r.link = link.name;
  r.method = method;
  r.before = link.inertial;
  r.after = after;
  r.inserts_inertial = !link.inertial.has_value();
  r.link_line = link.location.line;
  r.why = std::move(why);
  FillRepairChanges(model, link, &r);
  return r;
}

// What one link is asked to become.
struct Request {
  enum class Kind { kMass, kDensity } kind = Kind::kMass;
  double value = 0;      // kg or kg/m³
  std::string material;  // --material's label
};

// The link's mass and inertia from its closed meshes at `density`; false (with *error) when it
// has none.
bool FromClosedMesh(const Model& model, const Link& link, const Request& request,
                    const LinkShapeFunction& closed_mesh, Repair* repair, std::string* error) {
  const char* option = request.material.empty() ? "--density" : "--material";
  std::optional<LinkShape> shape;
  if (closed_mesh) shape = closed_mesh(link);
  if (!shape) {
    *error = std::string(option) + ": link '" + link.name +
             "' has no closed mesh (its visual, else collision, geometry must be meshes that "
             "resolve, read and are watertight: every edge shared by exactly two triangles) to "
             "compute its mass from";
    return false;
  }
  Inertial after = link.inertial ? *link.inertial : Inertial{};
  const Eigen::Matrix3d R = after.X_BBi.R_AB;
  after.mass = Round(request.value * shape->volume);
  for (int i = 0; i < 3; ++i) after.X_BBi.p_AB(i) = Round(shape->p_BoBcm_B(i));
  Eigen::Matrix3d I = R.transpose() * (after.mass * shape->G_BBcm_B) * R;
  // A mesh's 32-bit vertices leave products of about 1e-19 where the true value is 0: below 1e-9
  // of the trace they are written as 0 (as fix --from-geometry does).
  const double noise = 1e-9 * std::abs(I.trace());
  after.ixx = I(0, 0);
  after.iyy = I(1, 1);
  after.izz = I(2, 2);
  after.ixy = std::abs(I(0, 1)) <= noise ? 0 : 0.5 * (I(0, 1) + I(1, 0));
  after.ixz = std::abs(I(0, 2)) <= noise ? 0 : 0.5 * (I(0, 2) + I(2, 0));
  after.iyz = std::abs(I(1, 2)) <= noise ? 0 : 0.5 * (I(1, 2) + I(2, 1));
  ScaleInertia(1, &after);
  const std::string what = (request.material.empty() ? "density " : request.material + " (") +
                           Short(request.value) + " kg/m³" + (request.material.empty() ? "" : ")");
  *repair = MakeRepair(model, link, option, "from-closed-mesh", after,
                       "mass = " + what + " × volume " + Short(shape->volume) +
                           " m³ of its closed " + (shape->from_collision ? "collision" : "visual") +
                           " mesh = " + Short(after.mass) +
                           " kg, with the mesh's center of mass and inertia (solid, uniform)");
  return true;
}

}  // namespace

bool PlanMassRepairs(const Model& model, const MassRepairOptions& options,
                     std::vector<Repair>* repairs, std::string* error) {
  repairs->clear();
  std::map<std::string, Request> requests;  // by link name
  auto add = [&](const std::string& link, const char* option, Request request) {
    if (model.FindLink(link) < 0) {
      *error = std::string(option) + ": the model '" + model.name + "' has no link '" + link + "'";
      return false;
    }
    if (requests.count(link)) {
      *error = std::string(option) + ": link '" + link +
               "' is named twice (by --mass, --density or --material)";
      return false;
    }
    if (!(request.value > 0) || !std::isfinite(request.value)) {
      *error = std::string(option) + ": link '" + link + "': " + Short(request.value) +
               " is not a positive number";
      return false;
    }
    requests[link] = request;
    return true;
  };
  for (const auto& [link, kg] : options.link_masses) {
    if (!add(link, "--mass", {Request::Kind::kMass, kg, ""})) return false;
  }
  for (const LinkDensityRequest& d : options.link_densities) {
    if (!add(d.link, d.material.empty() ? "--density" : "--material",
             {Request::Kind::kDensity, d.density, d.material})) {
      return false;
    }
  }
  if (options.total_mass && (!(*options.total_mass > 0) || !std::isfinite(*options.total_mass))) {
    *error = "--total-mass: " + Short(*options.total_mass) + " is not a positive number of kg";
    return false;
  }

  std::map<std::string, Repair> by_link;
  double fixed = 0;     // the mass of the links --total-mass does not scale
  double scalable = 0;  // the mass of those it scales
  for (const Link& link : model.links) {
    const auto it = requests.find(link.name);
    const double mass = LinkMassProperties(link, model.format).mass;
    if (it == requests.end()) {
      const bool scales = link.inertial && !link.inertial_unreadable &&
                          std::isfinite(link.inertial->mass) && link.inertial->mass > 0;
      if (scales) {
        scalable += link.inertial->mass;
      } else if (mass > 0 && std::isfinite(mass)) {
        fixed += mass;  // an SDF link without <inertial>: its default 1 kg
      }
      continue;
    }
    const Request& request = it->second;
    Repair repair;
    if (request.kind == Request::Kind::kDensity) {
      if (!FromClosedMesh(model, link, request, options.closed_mesh, &repair, error)) return false;
      fixed += repair.after.mass;
    } else {
      if (!link.inertial || link.inertial_unreadable || !(link.inertial->mass > 0) ||
          !std::isfinite(link.inertial->mass)) {
        *error = "--mass: link '" + link.name +
                 "' has no <inertial> with a positive mass whose inertia could be scaled with it "
                 "(give it its mass and inertia from its mesh with --material or --density)";
        return false;
      }
      fixed += request.value;
      const double k = request.value / link.inertial->mass;
      if (k == 1) continue;
      Inertial after = *link.inertial;
      after.mass = request.value;
      ScaleInertia(k, &after);
      repair = MakeRepair(model, link, "--mass", "scale", after,
                          "the part weighs " + Short(request.value) + " kg (was " +
                              Short(link.inertial->mass) + " kg): mass and every inertia entry × " +
                              Short(k) + ", center of mass unchanged");
    }
    if (!repair.changes.empty() || repair.inserts_inertial) by_link[link.name] = repair;
  }

  if (options.total_mass) {
    const double total = *options.total_mass;
    const double rest = total - fixed;
    if (!(rest > 0)) {
      *error = "--total-mass " + Short(total) +
               " kg: the links whose masses are fixed (by --mass, "
               "--density, --material, or SDF's default 1 kg) already weigh " +
               Short(fixed) + " kg";
      return false;
    }
    if (!(scalable > 0)) {
      *error = "--total-mass " + Short(total) + " kg: no other link has a positive mass to scale";
      return false;
    }
    const double k = rest / scalable;
    if (std::abs(k - 1) > kTotalMassTolerance) {
      for (const Link& link : model.links) {
        if (requests.count(link.name) || !link.inertial || link.inertial_unreadable ||
            !(link.inertial->mass > 0) || !std::isfinite(link.inertial->mass)) {
          continue;
        }
        Inertial after = *link.inertial;
        after.mass = Round(after.mass * k);
        ScaleInertia(k, &after);
        Repair repair = MakeRepair(
            model, link, "--total-mass", "scale", after,
            "the model weighs " + Short(total) + " kg: the links not named share " + Short(rest) +
                " kg (they weighed " + Short(scalable) + " kg): mass and every inertia entry × " +
                Short(k) + ", center of mass unchanged");
        if (!repair.changes.empty()) by_link[link.name] = repair;
      }
    }
  }
  for (const Link& link : model.links) {
    const auto it = by_link.find(link.name);
    if (it != by_link.end()) repairs->push_back(it->second);
  }
  return true;
}

std::vector<Repair> ChainRepairs(const Model& model, const std::vector<Repair>& first,
                                 const std::vector<Repair>& second) {
  std::vector<Repair> chained;
  for (const Link& link : model.links) {
    const Repair* a = nullptr;
    const Repair* b = nullptr;
    for (const Repair& r : first) a = r.link == link.name ? &r : a;
    for (const Repair& r : second) b = r.link == link.name ? &r : b;
    if (!a && !b) continue;
    if (!b) {
      chained.push_back(*a);
      continue;
    }
    Repair r = *b;
    if (a) {
      r.rule = a->rule;
      r.method = a->method + "+" + b->method;
      r.why = a->why + "; then " + b->why;
    }
    r.before = link.inertial;
    r.inserts_inertial = !link.inertial.has_value();
    FillRepairChanges(model, link, &r);
    if (!r.changes.empty() || r.inserts_inertial) chained.push_back(std::move(r));
  }
  return chained;
}

}  // namespace massprops
