#include "massprops/analysis/density_rules.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "analysis/rule_severity.h"
#include "massprops/analysis/finding_text.h"
#include "massprops/analysis/link_measure.h"
#include "massprops/analysis/materials.h"
#include "massprops/analysis/welded_groups.h"

namespace massprops {
namespace {

// A number for a sentence: 4 significant digits.
std::string Num(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.4g", x);
  return buffer;
}

// The severity of `rule` after the overrides, or nullopt when it is off.
std::optional<Severity> SeverityOf(const char* rule, const CheckOptions& options) {
  return RuleSeverity(rule, options);
}

bool Ignores(const Link& link, const char* rule) {
  return std::any_of(link.ignored_rules.begin(), link.ignored_rules.end(),
                     [&](const std::string& id) { return id == rule || id == "all"; });
}

// A link whose mass has a density: its mass over the volume of its closed meshes.
struct LinkDensity {
  int index = 0;
  double mass = 0;
  double volume = 0;
  bool from_collision = false;
  double group_mass = 0;  // the mass of its welded group, itself included
  LinkShape shape;        // the closed meshes' uniform solid (per unit mass)
  double density() const { return mass / volume; }
};

// A marker: geometry too small to hold a body's mass as a solid, that is, geometry that the
// lightest solid (kMinSolidDensity) filling it would make at most kDummyMass heavy (an ArUco
// tag's sheet, a 1 cm frame marker), or at most kMarkerShare of the rest of its welded group (a
// logo badge or an antenna stub on a robot's body: whatever it weighs, the body it is welded to
// does not change). Its density means nothing. A small mass on a part of real size that moves on
// its own (a 1 g placeholder on a 4 x 9 x 6 cm gripper finger, 37 kg/m³) is judged.
constexpr double kDummyMass = 1e-3;    // kg
constexpr double kMarkerShare = 0.05;  // 5%: about what mass identification achieves

// "PLA 0.034 kg, ABS 0.028 kg, ..." for a volume (m³), over the common materials.
std::string MassesAt(double volume, double other_mass = 0) {
  std::string text;
  for (const Material& m : CommonMaterials()) {
    text +=
        (text.empty() ? "" : ", ") + m.label + " " + Num(m.density * volume + other_mass) + " kg";
  }
  return text;
}

const SourceLocation& MassLocation(const Link& link) {
  if (link.inertial->mass_location.line > 0) return link.inertial->mass_location;
  if (link.inertial->location.line > 0) return link.inertial->location;
  return link.location;
}

Finding MakeFinding(const char* rule, Severity severity, const Model& model, std::string link,
                    const SourceLocation& location, std::string message,
                    std::vector<std::pair<std::string, double>> values) {
  Finding f;
  f.rule = rule;
  f.severity = severity;
  f.model = model.name;
  f.link = std::move(link);
  f.location = location;
  f.message = std::move(message);
  f.values = std::move(values);
  return f;
}

// Above lead (11 340 kg/m³, CRC Handbook), the densest metal parts are cast or machined from,
// only tungsten alloys (17 000-19 300) and the precious metals are; a link's mesh reported denser
// must be beyond lead by kDenseMargin (a tessellated mesh's chord error and a rounded mass move a
// lead counterweight's density by well under 10%).
constexpr double kSteelDensity = 7850;  // what the part would weigh in steel, for the evidence
// The written inertial is the closed meshes' own uniform solid at the written mass when every
// principal moment is within kSolidMatch of the solid's trace and the center of mass within
// kSolidMatch of the solid's radius of gyration from its centroid: what an exporter that
// integrated the mesh writes (its numbers agree to the tessellation and the printed digits). A
// motor lumped on a bracket moves them by its share of the body (the labelled robots' lumped
// masses: 13% of the trace or more).
constexpr double kSolidMatch = 0.05;

// How far the written inertial is from the closed meshes' own uniform solid at the written mass.
struct SolidMatch {
  double moments = HUGE_VAL;  // largest |λ_i − μ_i| / tr(m·G) over the sorted principal moments
  double com = HUGE_VAL;      // |c − centroid| / the solid's radius of gyration sqrt(tr(G)/2)
  double com_m = HUGE_VAL;    // |c − centroid| (m)
  bool Matches() const { return moments <= kSolidMatch && com <= kSolidMatch; }
};

SolidMatch MatchSolid(const Link& link, Model::Format format, const LinkDensity& d) {
  SolidMatch fit;
  const MassProperties props = LinkMassProperties(link, format);
  const Eigen::Matrix3d solid = props.mass * d.shape.G_BBcm_B;
  const double trace = solid.trace();
  if (!(trace > 0) || !std::isfinite(trace) || !props.I_SScm_F.allFinite() ||
      !props.p_FoScm_F.allFinite()) {
    return fit;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> written(props.I_SScm_F,
                                                               Eigen::EigenvaluesOnly);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> own(solid, Eigen::EigenvaluesOnly);
  fit.moments = (written.eigenvalues() - own.eigenvalues()).cwiseAbs().maxCoeff() / trace;
  fit.com_m = (props.p_FoScm_F - d.shape.p_BoBcm_B).norm();
  fit.com = fit.com_m / std::sqrt(d.shape.G_BBcm_B.trace() / 2);
  return fit;
}

// density-implausible, too dense: a link whose written inertial is its closed meshes' uniform
// solid (the mass belongs to the drawn part) at a density beyond lead's. A mass lumped on a
// bracket (a servo, a knee motor its mesh does not draw) has another tensor and is not judged.
std::optional<Finding> CheckTooDense(const Model& model, const LinkDensity& d, Severity severity) {
  const Link& link = model.links[d.index];
  const double rho = d.density();
  if (!(rho > kDenseMargin * kLeadDensity)) return std::nullopt;
  const SolidMatch fit = MatchSolid(link, model.format, d);
  if (!fit.Matches()) return std::nullopt;
  const std::string what =
      std::string("its closed ") + (d.from_collision ? "collision" : "visual") + " mesh";
  std::string message =
      "link '" + link.name + "': mass " + Num(d.mass) + " kg over the volume " + Num(d.volume) +
      " m³ of " + what + " is a density of " + Num(rho) + " kg/m³, more than " + Num(kDenseMargin) +
      " times lead's 11340 kg/m³ (only tungsten alloys, 17000-19300, are " +
      "denser among the metals parts are made of); and its inertia is that mesh's as a uniform " +
      "solid of this mass (principal moments within " + Num(100 * fit.moments) +
      "% of the trace, center of mass " + Num(fit.com_m) +
      " m from the mesh's centroid), so the mass belongs to the drawn part, not to a motor " +
      "lumped on it (a mass typed for several parts, or in the wrong unit?); at common " +
      "densities the mesh's volume says: " + MassesAt(d.volume) + " (massprops fix --material " +
      link.name + "=NAME sets one, or --mass " + link.name + "=KG the weighed mass)";
  Finding f = MakeFinding(kDensityImplausibleRule, severity, model, link.name, MassLocation(link),
                          std::move(message),
                          {{"mass", d.mass},
                           {"volume", d.volume},
                           {"density", rho},
                           {"moment_difference", fit.moments},
                           {"com_offset", fit.com_m}});
  f.headline = "link '" + link.name + "': density " + FormatSignificant(rho) +
               " kg/m³, denser than lead, with its mesh's own inertia";
  if (f.headline.size() > kMaxHeadlineChars) {  // a long name: a shorter sentence, never a cut one
    f.headline =
        "link '" + link.name + "': denser than lead (" + FormatSignificant(rho) + " kg/m³)";
  }
  f.evidence = {{"mass_kg", d.mass},
                {"volume_m3", d.volume},
                {"density_kg_m3", rho},
                {"mass_if_steel_kg", kSteelDensity * d.volume}};
  f.help = "write the weighed mass, or run massprops fix --material LINK=NAME";
  return f;
}

// Whether a density-implausible finding of the hull's (rules/density_realizable.cc) is above
// osmium's density: its "density" value beyond 22 590 kg/m³ (kOsmiumDensity).
bool AboveOsmium(const Finding& f) {
  return std::any_of(f.values.begin(), f.values.end(), [](const auto& value) {
    return value.first == "density" && value.second > kOsmiumDensity;
  });
}

// density-implausible on one link.
std::optional<Finding> CheckDensity(const Model& model, const LinkDensity& d, Severity severity) {
  const Link& link = model.links[d.index];
  const double rho = d.density();
  // Too light here; too dense only where the mass is the mesh's own (CheckTooDense). A density
  // above lead's is no defect of the file by itself: a URDF link's mass is that of its moving
  // body, which often holds parts its mesh does not draw (a servo inside a bracket's mesh, a knee
  // motor behind a simplified shell; docs/rules.md).
  if (rho >= kMinSolidDensity) return CheckTooDense(model, d, severity);
  const double solid = d.volume * kMinSolidDensity;  // the lightest solid filling the geometry
  if (!(solid > kDummyMass) || !(solid > kMarkerShare * (d.group_mass - d.mass))) {
    return std::nullopt;  // a marker
  }
  const std::string what =
      std::string("its closed ") + (d.from_collision ? "collision" : "visual") + " mesh";
  std::string message = "link '" + link.name + "': mass " + Num(d.mass) + " kg over the volume " +
                        Num(d.volume) + " m³ of " + what + " is a density of " + Num(rho) +
                        " kg/m³, ";
  message +=
      "below 100"
      " kg/m³: only foams and aerogels are that light (a placeholder mass?)";
  const double millimetres = rho * 1e9;
  if (millimetres >= kMinSolidDensity && millimetres <= kMaxSolidDensity) {
    message +=
        "; were the mesh in millimetres without scale=\"0.001 0.001 0.001\", the part "
        "would be " +
        Num(millimetres) + " kg/m³";
  }
  message += "; at common densities the mesh's volume says: " + MassesAt(d.volume) +
             " (massprops fix --material " + link.name + "=NAME sets one, or --mass " + link.name +
             "=KG the weighed mass)";
  Finding f =
      MakeFinding(kDensityImplausibleRule, severity, model, link.name, MassLocation(link),
                  std::move(message), {{"mass", d.mass}, {"volume", d.volume}, {"density", rho}});
  const bool mesh_in_mm = millimetres >= kMinSolidDensity && millimetres <= kMaxSolidDensity;
  f.headline = LinkHeadline(
      link.name, ": density " + FormatSignificant(rho) +
                     " kg/m³ over its closed mesh, lighter than foam (" +
                     (mesh_in_mm ? "mesh in mm without scale?" : "placeholder mass?") + ")");
  f.evidence = {{"mass_kg", d.mass}, {"volume_m3", d.volume}, {"density_kg_m3", rho}};
  f.help = "write the weighed mass, or run massprops fix --material LINK=NAME";
  return f;
}

// cad-default-density on the model: every link with a density at 1000 kg/m³.
std::optional<Finding> CheckCadDefault(const Model& model, const std::vector<LinkDensity>& all,
                                       Severity severity) {
  std::vector<LinkDensity> counted;
  for (const LinkDensity& d : all) {
    if (!Ignores(model.links[d.index], kCadDefaultDensityRule)) counted.push_back(d);
  }
  if (static_cast<int>(counted.size()) < kCadDefaultDensityMinLinks) return std::nullopt;
  double lowest = HUGE_VAL, highest = 0, volume = 0, counted_mass = 0;
  for (const LinkDensity& d : counted) {
    const double rho = d.density();
    if (std::abs(rho / kCadDefaultDensity - 1) > kCadDefaultDensityTolerance) return std::nullopt;
    lowest = std::min(lowest, rho);
    highest = std::max(highest, rho);
    volume += d.volume;
    counted_mass += d.mass;
  }
  double total = 0;
  for (const Link& link : model.links) {
    const double m = LinkMassProperties(link, model.format).mass;
    if (m > 0 && std::isfinite(m)) total += m;
  }
  const double others = std::max(0.0, total - counted_mass);
  std::string message =
      "no material was assigned in the CAD export (SolidWorks' default density of 1000 kg/m³): "
      "the " +
      std::to_string(counted.size()) +
      " links with closed meshes all have mass = mesh "
      "volume × 1000 kg/m³ (" +
      Num(lowest) + " to " + Num(highest) + " kg/m³, within " +
      Num(100 * kCadDefaultDensityTolerance) + "%), so the model's " + Num(total) +
      " kg is what it would weigh made of water; made of one material it would weigh " +
      MassesAt(volume, others) +
      " — set the materials in CAD and export again, or massprops fix --material LINK=NAME, "
      "--mass LINK=KG, --total-mass KG";
  const Link* first = &model.links[counted.front().index];
  const SourceLocation& location = model.location.line > 0 ? model.location : first->location;
  Finding f = MakeFinding(kCadDefaultDensityRule, severity, model, "", location, std::move(message),
                          {{"links", static_cast<double>(counted.size())},
                           {"total_mass", total},
                           {"volume", volume},
                           {"density_min", lowest},
                           {"density_max", highest}});
  f.headline = ModelHeadline(model.name, ": all " + std::to_string(counted.size()) +
                                             " links with closed meshes weigh 1000 kg/m³ (CAD "
                                             "default, no material set?)");
  f.evidence = {{"links_count", static_cast<double>(counted.size())},
                {"total_mass_kg", total},
                {"density_min_kg_m3", lowest},
                {"density_max_kg_m3", highest}};
  f.help = "set the materials in CAD and export again, or massprops fix --material LINK=NAME";
  return f;
}

}  // namespace

const std::vector<RuleInfo>& DensityRules() {
  static const std::vector<RuleInfo> kRules = {
      {kDensityImplausibleRule, Severity::kWarning, true,
       "A link's mass over the volume of its closed meshes is a density no solid part has "
       "(below 100 kg/m³: only foams; above 1.1 times lead where the inertia is the mesh's own "
       "uniform solid), or over the hull of its whole geometry: above osmium, or above 1.1 times "
       "lead where meshes draw it; markers (meshes that would hold at most 1 g at 100 kg/m³, or "
       "5% of their welded group) are not judged."},
      {kCadDefaultDensityRule, Severity::kWarning, true,
       "Every link with closed meshes (at least 2) has mass = volume × 1000 kg/m³ within 1%: the "
       "CAD export had no material (SolidWorks' default density); said once per model."},
  };
  return kRules;
}

void AddDensityFindings(const Model& model, const CheckOptions& options,
                        std::vector<Finding>* findings) {
  if (!options.closed_mesh) return;
  const std::optional<Severity> implausible = SeverityOf(kDensityImplausibleRule, options);
  const std::optional<Severity> cad_default = SeverityOf(kCadDefaultDensityRule, options);
  if (!implausible && !cad_default) return;
  std::vector<LinkDensity> densities;
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const Link& link = model.links[i];
    if (!link.inertial || link.inertial_unreadable || link.geometries.empty()) continue;
    const double mass = link.inertial->mass;
    if (!(mass > 0) || !std::isfinite(mass)) continue;
    const std::optional<LinkShape> shape = options.closed_mesh(link);
    if (!shape || !(shape->volume > 0) || !std::isfinite(shape->volume)) continue;
    densities.push_back(
        {static_cast<int>(i), mass, shape->volume, shape->from_collision, 0, *shape});
  }
  if (!densities.empty()) {
    std::vector<double> group_mass(model.links.size(), 0);
    for (const WeldedGroup& group : FindWeldedGroups(model)) {
      double m = 0;
      for (int i : group.links) {
        const double mi = LinkMassProperties(model.links[i], model.format).mass;
        if (mi > 0 && std::isfinite(mi)) m += mi;
      }
      for (int i : group.links) group_mass[i] = m;
    }
    for (LinkDensity& d : densities) d.group_mass = group_mass[d.index];
  }
  const std::size_t before = findings->size();
  if (implausible) {
    // The links units-suspect found, and the first hull density finding of each link, looked up
    // once (a scan of the findings per link would cost links x findings). Names copied: the
    // findings grow below.
    std::unordered_set<std::string> unit_slips;
    std::unordered_map<std::string, std::size_t> hull_finding;
    for (std::size_t k = 0; k < before; ++k) {
      const Finding& f = (*findings)[k];
      if (f.rule == "units-suspect") unit_slips.insert(f.link);
      if (f.rule == kDensityImplausibleRule) hull_finding.emplace(f.link, k);
    }
    for (const LinkDensity& d : densities) {
      if (Ignores(model.links[d.index], kDensityImplausibleRule)) continue;
      // One finding per defect: where units-suspect already finds the link's radius of gyration
      // out of proportion with its geometry (a mass in grams, a mesh in millimetres), that
      // finding says it; the density would repeat the same unit slip.
      const std::string& name = model.links[d.index].name;
      if (unit_slips.count(name) != 0) continue;
      std::optional<Finding> f = CheckDensity(model, d, *implausible);
      if (!f) continue;
      // The hull of the link's whole geometry may have found it too dense already
      // (rules/density_realizable.cc): this finding, about its closed meshes' own solid, says
      // more than the hull's denser-than-lead and takes its place; the hull's denser than osmium
      // (no body of that mass fits at all) says more than either and stays.
      const auto hull = hull_finding.find(name);
      if (hull == hull_finding.end()) {
        findings->push_back(std::move(*f));
      } else if (!AboveOsmium((*findings)[hull->second])) {
        (*findings)[hull->second] = std::move(*f);
      }
    }
  }
  if (cad_default) {
    if (std::optional<Finding> f = CheckCadDefault(model, densities, *cad_default)) {
      findings->push_back(std::move(*f));
    }
  }
  if (findings->size() == before) return;
  std::stable_sort(findings->begin(), findings->end(), [](const Finding& a, const Finding& b) {
    if (a.location.line != b.location.line) return a.location.line < b.location.line;
    return a.rule < b.rule;
  });
}

}  // namespace massprops
