#pragma once
// Private to analysis: the judging of planned repairs (repair_judge.cc, used by PlanRepairs in
// repair.cc): each repair checked again against the findings of the model as it is, dropped when
// it leaves or creates a finding, its numbers rounded to the fewest digits that still pass, and
// the findings it resolves.
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "massprops/analysis/checks.h"
#include "massprops/analysis/repair.h"

namespace massprops::internal {

using RulesOfLinks = std::map<std::string, std::set<std::string>>;  // link -> rules
using LinkRule = std::pair<std::string, std::string>;               // (link, rule)

// Checks repairs again against the findings of the model as it is (not the findings given, which
// may come from other options): a repair must make the findings it answers go away and create
// none the model did not have, on any link.
class RepairJudge {
 public:
  RepairJudge(const Model& model, const RepairOptions& options) : model_(model) {
    check_options_.tolerance = options.tolerance;
    check_options_.shape = options.shape;
    check_options_.box = options.box;
    check_options_.points = options.points;
    for (const Finding& f : CheckModel(model, check_options_)) {
      before_.insert({f.link, f.rule});
      // Mass given to a body outboard of a massless moving group turns the group's error into
      // this note: the same massless body, now harmless, not a finding the repair creates.
      if (f.rule == "massless-moving-body") {
        before_.insert({f.link, "massless-link-with-mass-outboard"});
      }
    }
  }

  // What is wrong with `repair` when `all` (which holds it) are applied: a finding it answers
  // is left (judged with all of them applied: a welded group's finding may need every link of
  // the group repaired), or it creates a finding the model did not have (judged with it alone).
  // The same as findings: (true: it leaves it, false: it creates it, finding).
  std::vector<std::pair<bool, Finding>> ProblemFindings(const Repair& repair,
                                                        const std::vector<Repair>& all) const {
    std::vector<std::pair<bool, Finding>> found;
    for (const Finding& f : CheckModel(ApplyRepairs(model_, all), check_options_)) {
      if (f.link == repair.link &&
          std::find(repair.answers.begin(), repair.answers.end(), f.rule) != repair.answers.end()) {
        found.emplace_back(true, f);
      }
    }
    for (const Finding& f : CheckModel(ApplyRepairs(model_, {repair}), check_options_)) {
      if (!before_.count({f.link, f.rule})) found.emplace_back(false, f);
    }
    return found;
  }

  std::vector<std::string> Problems(const Repair& repair, const std::vector<Repair>& all) const {
    std::vector<std::string> found;
    for (const auto& [leaves, f] : ProblemFindings(repair, all)) {
      found.push_back(leaves ? "it leaves " + f.rule + ": " + f.message
                             : "it creates " + f.rule +
                                   (f.link.empty() ? "" : " on link '" + f.link + "'") + ": " +
                                   f.message);
    }
    return found;
  }

  const Model& model() const { return model_; }

  const CheckOptions& check_options() const { return check_options_; }

 private:
  const Model& model_;
  CheckOptions check_options_;
  std::set<LinkRule> before_;  // the findings of the model as it is
};

// Drops the repairs that have problems, one at a time (each drop changes what the others are
// judged with) until every one left passes; each dropped one is added to `refused` when given.
void DropFailingRepairs(const RepairJudge& judge, std::vector<Repair>* repairs,
                        std::vector<RefusedRepair>* refused);

// The numbers of each repair: the fewest significant digits (at least 6) that still pass.
void RoundRepairs(const Model& model, const RepairJudge& judge, std::vector<Repair>* repairs);

// Which findings each repair resolves: those of its link that are gone from the model with all
// the repairs applied.
void FindResolved(const Model& model, const CheckOptions& check_options,
                  const RulesOfLinks& rules_of, std::vector<Repair>* repairs);

}  // namespace massprops::internal
