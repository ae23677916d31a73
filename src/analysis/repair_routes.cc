// The ways forward for one link of `massprops fix` (repair_routes.h).
#include "massprops/analysis/repair_routes.h"

#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "massprops/analysis/finding_text.h"

namespace massprops {
namespace {

// The rules whose finding may come from a wrong mass: a scale or a datasheet answers them.
bool MassIsTheQuestion(const std::set<std::string>& rules) {
  static const char* const kMassRules[] = {"mass-not-positive",   "massless-moving-body",
                                           "inertial-missing",    "units-suspect",
                                           "density-implausible", "cad-default-density"};
  return std::any_of(std::begin(kMassRules), std::end(kMassRules),
                     [&](const char* rule) { return rules.count(rule) > 0; });
}

bool HasMesh(const Link& link) {
  return std::any_of(link.geometries.begin(), link.geometries.end(),
                     [](const Geometry& g) { return g.type == Geometry::Type::kMesh; });
}

// The repair options of a route: fix's own, without the heuristics and links it asked for, and
// with the meshes of `link` alone read (the other links are judged as fix judges them without
// --geometry, so a route costs one link's meshes).
RepairOptions RouteOptions(const RepairOptions& options, const std::string& link) {
  RepairOptions route = options;
  route.apply.clear();
  route.fix_units = false;
  route.from_geometry_all = false;
  route.from_geometry_links.clear();
  if (options.shape) {
    route.shape = [shape = options.shape, link](const Link& l) -> std::optional<LinkShape> {
      if (l.name != link) return std::nullopt;
      return shape(l);
    };
  }
  return route;
}

// Whether `repairs` leave no error on `link` (judged as the planner judges, CheckOptions from
// the route's RepairOptions).
bool LeavesNoError(const Model& model, const std::vector<Repair>& repairs, const std::string& link,
                   const RepairOptions& options) {
  CheckOptions check;
  check.tolerance = options.tolerance;
  check.shape = options.shape;
  check.box = options.box;
  check.points = options.points;
  const std::vector<Finding> after = CheckModel(ApplyRepairs(model, repairs), check);
  return std::none_of(after.begin(), after.end(), [&](const Finding& f) {
    return f.link == link && f.severity == Severity::kError;
  });
}

// Whether `repairs` hold a repair of `link`.
bool Repairs(const std::vector<Repair>& repairs, const std::string& link) {
  return std::any_of(repairs.begin(), repairs.end(),
                     [&](const Repair& r) { return r.link == link; });
}

// Whether a route of these repairs would write what `written` writes for the link.
bool SameAsWritten(const std::vector<Repair>& repairs, const Repair* written) {
  if (written == nullptr) return false;
  return std::any_of(repairs.begin(), repairs.end(), [&](const Repair& r) {
    return r.link == written->link && r.method == written->method;
  });
}

// What a heuristic rule's repair writes, in a few words, and the guess it makes.
std::pair<std::string, std::string> HeuristicWhat(const std::string& rule, double density) {
  if (rule == "units-suspect") return {"the one unit factor that fits its size", "a unit slip"};
  if (rule == "products-sign-suspect") return {"its products of inertia negated", "a sign slip"};
  if (rule == "inertia-about-origin-suspect") {
    return {"its inertia shifted to its COM", "an inertia about the origin"};
  }
  return {"its geometry's mass at " + FormatSignificant(density) + " kg/m³ (--density RHO)",
          "a uniform solid"};
}

// The route of this run's repair, of --from-geometry, of --repair balance and of each heuristic
// not asked for, those whose repair passes and leaves no error on the link.
void AddComputedRoutes(const Model& model, const std::vector<Finding>& own,
                       const std::set<std::string>& rules, const std::string& link,
                       const RepairOptions& options, const Repair* written,
                       std::vector<RepairRoute>* routes) {
  const RepairOptions base = RouteOptions(options, link);
  auto add = [&](std::string route_options, std::string what, bool physics, std::string basis,
                 const std::vector<Repair>& repairs, const RepairOptions& judged_with) {
    if (!Repairs(repairs, link) || SameAsWritten(repairs, written)) return;
    if (!LeavesNoError(model, repairs, link, judged_with)) return;
    routes->push_back(
        {std::move(route_options), std::move(what), physics, std::move(basis), repairs});
  };
  RepairOptions geometry = base;
  geometry.from_geometry_links = {link};
  add("--from-geometry=" + link, "its geometry's own inertia at its mass", false, "a uniform solid",
      PlanRepairs(model, {}, geometry), geometry);
  if (rules.count("inertia-not-physical") && options.method == InertiaRepairMethod::kProject) {
    RepairOptions balance = base;
    balance.method = InertiaRepairMethod::kBalance;
    add("--repair balance", "its principal moments set to their mean", false, "equal moments",
        PlanRepairs(model, own, balance), balance);
  }
  for (const std::string& rule : HeuristicRepairRules()) {
    const bool asked = std::any_of(options.apply.begin(), options.apply.end(),
                                   [&](const std::string& a) { return a == rule || a == "all"; });
    if (!rules.count(rule) || asked) continue;
    RepairOptions heuristic = base;
    heuristic.apply = {rule};
    auto [what, basis] = HeuristicWhat(rule, options.density);
    add("--apply " + rule, std::move(what), false, std::move(basis),
        PlanRepairs(model, own, heuristic), heuristic);
  }
}

// The method's basis: physics (the nearest valid inertia, the engineer's mass) or a guess.
std::pair<bool, std::string> MethodBasis(const std::string& method) {
  const std::string last =
      method.substr(method.rfind('+') == std::string::npos ? 0 : method.rfind('+') + 1);
  if (method == "project") return {true, "the nearest valid inertia"};
  if (method == "scale") return {true, "your mass"};
  if (last == "balance") return {false, "equal moments"};
  if (last.rfind("from-geometry", 0) == 0 || last == "from-closed-mesh") {
    return {false, "a uniform solid"};
  }
  return {false, "a guess from the numbers"};
}

}  // namespace

std::vector<RepairRoute> FindRepairRoutes(const Model& model, const std::vector<Finding>& findings,
                                          const std::string& link, const RepairOptions& options,
                                          const Repair* written) {
  std::vector<RepairRoute> routes;
  const int index = model.FindLink(link);
  if (index < 0) return routes;
  const Link& the_link = model.links[index];
  std::vector<Finding> own;
  std::set<std::string> rules;
  for (const Finding& f : findings) {
    if (f.link != link) continue;
    own.push_back(f);
    rules.insert(f.rule);
  }
  if (written != nullptr) {
    const auto [physics, basis] = MethodBasis(written->method);
    routes.push_back({"", written->method, physics, basis, {*written}});
  }
  AddComputedRoutes(model, own, rules, link, options, written, &routes);
  if (MassIsTheQuestion(rules)) {
    if (the_link.inertial && the_link.inertial->mass > 0) {
      routes.push_back({"--mass " + link + "=KG",
                        "the part's weighed mass, its inertia scaled",
                        true,
                        "a scale or datasheet",
                        {}});
    }
    if (HasMesh(the_link)) {
      routes.push_back({"--material " + link + "=NAME",
                        "the mass of its closed mesh in NAME",
                        false,
                        "one solid material",
                        {}});
    }
  }
  routes.push_back(
      {"", "its mass, COM and inertia from its CAD model or datasheet", true, "the real part", {}});
  return routes;
}

}  // namespace massprops
