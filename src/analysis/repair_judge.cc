// The judging of planned repairs (repair_judge.h).
#include "analysis/repair_judge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "massprops/analysis/finding_text.h"
#include "massprops/analysis/fix_text.h"

namespace massprops::internal {
namespace {

// x rounded to `digits` significant decimal digits.
double RoundToDigits(double x, int digits) {
  if (x == 0 || !std::isfinite(x)) return x;
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*e", digits - 1, x);
  return std::strtod(buffer, nullptr);
}

// Rounds the numbers of `after` that differ from `before` (all of them when there is no before)
// to `digits` significant digits; numbers the repair keeps stay exactly as written, and so does
// the precision of a number that was written with more digits.
void RoundChanged(const std::optional<Inertial>& before, int digits, Inertial* after) {
  // A number written with more digits than `digits` is written with as many as it had (a negation
  // or a rescaling does not throw away the file's precision, nor adds digits it never had).
  auto round = [&](double old_value, double* x) {
    if (before && old_value == *x) return;
    int precision = digits;
    if (before) {
      while (precision < 17 && RoundToDigits(old_value, precision) != old_value) ++precision;
    }
    *x = RoundToDigits(*x, precision);
  };
  const Inertial b = before ? *before : Inertial{};
  round(b.mass, &after->mass);
  for (int i = 0; i < 3; ++i) round(b.X_BBi.p_AB(i), &after->X_BBi.p_AB(i));
  round(b.ixx, &after->ixx);
  round(b.iyy, &after->iyy);
  round(b.izz, &after->izz);
  round(b.ixy, &after->ixy);
  round(b.ixz, &after->ixz);
  round(b.iyz, &after->iyz);
}

// What the repair's method writes, as the subject of a sentence: "its nearest valid inertia".
std::string MethodSubject(const std::string& method) {
  const std::string last =
      method.substr(method.rfind('+') == std::string::npos ? 0 : method.rfind('+') + 1);
  if (last == "project") return "its nearest valid inertia";
  if (last == "balance") return "its balanced inertia";
  if (last == "rescale-units") return "its inertia in the unit that fits";
  if (last == "negate-products") return "its inertia with products negated";
  if (last == "shift-to-com") return "its inertia shifted to its COM";
  if (last == "from-geometry-density") return "the mass from its geometry";
  if (last == "from-geometry") return "its geometry's inertia";
  return "the repair (" + method + ")";
}

// "mesh", "box", "cylinder", ... or "geometry": what the link's geometry is, in one word.
std::string GeometryWord(const Link& link) {
  std::string word;
  for (const Geometry& g : link.geometries) {
    static const char* const kWords[] = {"box",       "cylinder", "sphere",  "capsule",
                                         "ellipsoid", "mesh",     "geometry"};
    const std::string w = kWords[static_cast<int>(g.type)];
    if (!word.empty() && word != w) return "geometry";
    word = w;
  }
  return word.empty() ? "size" : word;
}

// The refusal of `repair` for the problems found: its reason at a glance, the numbers that
// decided as whole lines, the long form in `why`.
RefusedRepair DescribeRefusal(const Model& model, const Repair& repair,
                              const std::vector<std::pair<bool, Finding>>& found) {
  RefusedRepair refusal{repair.rule, repair.link, repair.link_line, "", "", {}, repair};
  refusal.why = "the repair (" + repair.method + ") does not pass the checks: ";
  for (std::size_t j = 0; j < found.size(); ++j) {
    const auto& [leaves, f] = found[j];
    refusal.why += (j ? "; " : "") + std::string(leaves ? "it leaves " : "it creates ") + f.rule +
                   (f.link.empty() || leaves ? "" : " on link '" + f.link + "'") + ": " + f.message;
  }
  refusal.why += " — not repaired";
  const int index = model.FindLink(repair.link);
  const std::string shape = index < 0 ? "size" : GeometryWord(model.links[index]);
  const auto& [leaves, first] = found.front();
  const std::string subject = MethodSubject(repair.method);
  if (leaves) {
    refusal.reason = subject + " still has " + first.rule;
  } else if (first.link == repair.link &&
             (first.rule.find("geometry") != std::string::npos || first.rule == "units-suspect" ||
              first.rule == "density-implausible")) {
    refusal.reason = subject + " does not fit its " + shape + " either";
  } else {
    refusal.reason = subject + " would draw " + first.rule;
  }
  if (repair.before) {
    refusal.evidence.push_back("principal moments " +
                               FormatTriple(PrincipalMomentsOf(*repair.before)) + " kg·m², " +
                               (repair.method == "project" ? "the nearest valid ones " : "after ") +
                               FormatTriple(PrincipalMomentsOf(repair.after)));
  }
  for (const auto& [left, f] : found) {
    const std::string lead =
        (left ? "still " : "then ") + f.rule +
        (f.link.empty() || f.link == repair.link ? "" : " on '" + f.link + "'") + ": ";
    const std::string values = FormatWholeEvidence(f.values, 86 - CountChars(lead));
    refusal.evidence.push_back(values.empty() ? HeadlineOf(f) : lead + values);
  }
  return refusal;
}

}  // namespace

// Drops the repairs that have problems, one at a time (each drop changes what the others are
// judged with) until every one left passes; each dropped one is added to `refused` when given.
void DropFailingRepairs(const RepairJudge& judge, std::vector<Repair>* repairs,
                        std::vector<RefusedRepair>* refused) {
  for (bool changed = true; changed && !repairs->empty();) {
    changed = false;
    for (std::size_t i = 0; i < repairs->size(); ++i) {
      const Repair& repair = (*repairs)[i];
      const std::vector<std::pair<bool, Finding>> found = judge.ProblemFindings(repair, *repairs);
      if (found.empty()) continue;
      if (refused) refused->push_back(DescribeRefusal(judge.model(), repair, found));
      repairs->erase(repairs->begin() + static_cast<std::ptrdiff_t>(i));
      changed = true;
      break;
    }
  }
}

// The numbers of each repair: the fewest significant digits (at least 6) that still pass.
void RoundRepairs(const Model& model, const RepairJudge& judge, std::vector<Repair>* repairs) {
  for (std::size_t i = 0; i < repairs->size(); ++i) {
    const int index = model.FindLink((*repairs)[i].link);
    if (index < 0) continue;
    const Link& link = model.links[index];
    for (int digits = 6; digits <= 16; ++digits) {
      std::vector<Repair> trial = *repairs;
      RoundChanged(link.inertial, digits, &trial[i].after);
      if (!judge.Problems(trial[i], trial).empty()) continue;
      FillRepairChanges(model, link, &trial[i]);
      (*repairs)[i] = std::move(trial[i]);
      break;
    }
  }
}

// Which findings each repair resolves: those of its link that are gone from the model with all
// the repairs applied.
void FindResolved(const Model& model, const CheckOptions& check_options,
                  const RulesOfLinks& rules_of, std::vector<Repair>* repairs) {
  const std::vector<Finding> after = CheckModel(ApplyRepairs(model, *repairs), check_options);
  std::set<LinkRule> remaining;
  for (const Finding& f : after) remaining.insert({f.link, f.rule});
  for (Repair& repair : *repairs) {
    const auto it = rules_of.find(repair.link);
    if (it == rules_of.end()) continue;
    for (const std::string& rule : it->second) {
      if (!remaining.count({repair.link, rule})) repair.resolves.push_back(rule);
    }
  }
}

}  // namespace massprops::internal
