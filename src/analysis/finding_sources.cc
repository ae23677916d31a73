#include "massprops/analysis/finding_sources.h"

#include <cstdlib>
#include <utility>

namespace massprops {
namespace {

// The numbers a rule is about, most telling first: the products for products-sign-suspect, the
// mass for the mass rules, the origin for com-outside-geometry; empty: the finding's own line.
std::vector<std::pair<std::string, std::string>> NumbersOfRule(const std::string& rule) {
  if (rule == "products-sign-suspect") {
    return {{"inertia", "ixy"}, {"inertia", "ixz"}, {"inertia", "iyz"}};
  }
  if (rule == "mass-not-positive" || rule == "massless-moving-body" ||
      rule == "drake-rejects-massless-body") {
    return {{"mass", "value"}};
  }
  if (rule == "com-outside-geometry") return {{"origin", "xyz"}};
  return {};
}

bool IsZero(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  return end != text.c_str() && value == 0;
}

}  // namespace

void AttachXacroSources(const XacroTrace& trace, const std::string& generated_name,
                        std::vector<Finding>* findings) {
  for (Finding& finding : *findings) {
    if (finding.link.empty()) continue;
    const TracedNumber* chosen = nullptr;
    // The rule's own numbers (a non-zero one first), then the link's numbers on the finding's
    // line, then its inertia, mass, origin.
    for (bool nonzero : {true, false}) {
      for (const auto& [element, attribute] : NumbersOfRule(finding.rule)) {
        for (const TracedNumber& n : trace.numbers) {
          if (chosen || n.link != finding.link || n.places.empty()) continue;
          if (n.element != element || n.attribute != attribute) continue;
          if (nonzero && IsZero(n.expanded_value)) continue;
          chosen = &n;
        }
      }
    }
    for (const char* element : {"", "inertia", "mass", "origin"}) {
      for (const TracedNumber& n : trace.numbers) {
        if (chosen) break;
        if (n.link != finding.link || n.places.empty()) continue;
        const bool on_line = *element == '\0' && n.expanded_line == finding.location.line;
        if (on_line || (*element != '\0' && n.element == element)) chosen = &n;
      }
    }
    if (!chosen) continue;
    FindingSource source;
    source.number = NumberName(*chosen);
    source.places = chosen->places;
    source.generated = finding.location;
    source.generated.file = generated_name;
    finding.source = std::move(source);
  }
}

}  // namespace massprops
