#include "massprops/analysis/finding_sources.h"

#include <utility>

namespace massprops {

void AttachXacroSources(const XacroTrace& trace, const std::string& generated_name,
                        std::vector<Finding>* findings) {
  for (Finding& finding : *findings) {
    if (finding.link.empty()) continue;
    const TracedNumber* chosen = nullptr;
    // The numbers of the finding's link on its line first; then inertia, mass, origin.
    for (const char* element : {"", "inertia", "mass", "origin"}) {
      for (const TracedNumber& n : trace.numbers) {
        if (n.link != finding.link || n.places.empty()) continue;
        const bool on_line = *element == '\0' && n.expanded_line == finding.location.line;
        if (on_line || (*element != '\0' && n.element == element)) {
          chosen = &n;
          break;
        }
      }
      if (chosen) break;
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
