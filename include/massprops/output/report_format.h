#pragma once
/// @file
/// The mass report (analysis/mass_report.h) as text, JSON or CSV.

#include <ostream>
#include <string>
#include <vector>

#include "massprops/analysis/mass_report.h"

namespace massprops {

/// Output formats of the report.
enum class MassReportFormat { kText, kJson, kCsv };

/// An input file that could not be reported, for the renderings.
struct MassReportError {
  std::string file;
  int line = 0;
  std::string message;
};

/// Writes the reports: JSON as documented in docs/report.md ({"models":[...],"errors":[...]}),
/// numbers round-trip exactly; CSV one row per body (header first), numbers with max_digits10;
/// text aligned tables with 6 significant digits and notes (no equivalent box, unreachable links,
/// digits lost above `digits_lost_threshold`). `errors` appear only in JSON (the tool prints them
/// to standard error for text and CSV). Never throws except for stream errors.
void WriteMassReport(std::ostream& out, MassReportFormat format,
                     const std::vector<ModelMassReport>& reports,
                     const std::vector<MassReportError>& errors = {},
                     double digits_lost_threshold = 6);

}  // namespace massprops
