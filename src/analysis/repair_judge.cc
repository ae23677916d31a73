// The judging of planned repairs (repair_judge.h).
#include "analysis/repair_judge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

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

}  // namespace

// Drops the repairs that have problems, one at a time (each drop changes what the others are
// judged with) until every one left passes; each dropped one is added to `refused` when given.
void DropFailingRepairs(const RepairJudge& judge, std::vector<Repair>* repairs,
                        std::vector<RefusedRepair>* refused) {
  for (bool changed = true; changed && !repairs->empty();) {
    changed = false;
    for (std::size_t i = 0; i < repairs->size(); ++i) {
      const Repair& repair = (*repairs)[i];
      const std::vector<std::string> found = judge.Problems(repair, *repairs);
      if (found.empty()) continue;
      if (refused) {
        std::string why = "the repair (" + repair.method + ") does not pass the checks: ";
        for (std::size_t j = 0; j < found.size(); ++j) why += (j ? "; " : "") + found[j];
        why += " — not repaired; look at this link's mass, center of mass and inertia by hand";
        refused->push_back({repair.rule, repair.link, repair.link_line, why});
      }
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
