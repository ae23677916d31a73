// `massprops explain RULE` (issue 32, like `rustc --explain` and `ruff rule`): the rule's long
// form, offline, from the binary: what it means, the physics and the evidence it reads, a worked
// example, how to fix it and how to silence it. The text is the rule's section of docs/rules.md,
// compiled into the library (analysis/finding_text.h), so the two cannot drift apart. Exit codes:
// 0 printed; 2 an unknown rule (the rules are listed on standard error).
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "commands.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/finding_text.h"

namespace massprops::cli {
namespace {

constexpr int kExplainClean = 0;
constexpr int kExplainUnknown = 2;

int RunExplain(const std::string& rule) {
  if (const std::optional<std::string> text = RuleLongForm(rule)) {
    std::cout << *text;
    return kExplainClean;
  }
  std::cerr << "massprops: error: unknown rule '" << rule << "'; the rules are:\n";
  for (const RuleInfo& info : AllRules()) std::cerr << "  " << info.id << "\n";
  return kExplainUnknown;
}

}  // namespace

void AddExplainCommand(CLI::App& app, std::function<int()>* run) {
  auto rule = std::make_shared<std::string>();
  CLI::App* explain = app.add_subcommand(
      "explain",
      "Print a rule's long form: what it means, the physics and evidence it reads, an example, "
      "how to fix it and how to silence it (the rules: massprops check --list-rules)");
  explain->add_option("RULE", *rule, "A rule id, e.g. units-suspect")->required();
  explain->callback([run, rule] { *run = [rule] { return RunExplain(*rule); }; });
}

}  // namespace massprops::cli
