// `massprops fix` (no options) over ../shared/corpus (MANIFEST.tsv): every file is fixed; only
// links with an error finding change (a file without errors not at all); the fix may change only
// lines inside <inertial> elements (or insert new ones), the fixed file reads back, has no
// finding the original lacked and no error left that a repair exists for, and fixing it again
// changes nothing. Prints the per-source table of docs/fix.md.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "corpus_manifest.h"
#include "massprops/analysis/checks.h"
#include "massprops/analysis/repair.h"
#include "massprops/io/model_reader.h"
#include "massprops/output/xml_patch.h"

namespace massprops {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = MASSPROPS_CORPUS_DIR;

struct Entry {
  std::string file;
  std::string source;
};

std::vector<Entry> ReadManifest() {
  std::vector<Entry> entries;
  for (const test_support::ManifestRow& row : test_support::ReadCorpusManifest()) {
    entries.push_back({row.file, row.source_repo});
  }
  return entries;
}

// Whether each line (0-based) lies inside an <inertial> element (text scan, independent of the
// patcher's XML scanner).
std::vector<bool> InertialLines(const std::string& text) {
  std::vector<bool> inside;
  bool open = false;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const bool opens = line.find("<inertial") != std::string::npos;
    const bool closes = line.find("</inertial>") != std::string::npos ||
                        (opens && line.find("/>", line.find("<inertial")) != std::string::npos &&
                         line.find('<', line.find("<inertial") + 1) == std::string::npos);
    inside.push_back(open || opens || closes);
    if (opens) open = true;
    if (closes) open = false;
  }
  return inside;
}

struct Counts {
  int files = 0, fixed = 0, links_repaired = 0;
  int errors_before = 0, errors_after = 0, warnings_before = 0, warnings_after = 0;
};

struct Fixed {
  std::string text;
  int repairs = 0;
  std::set<std::string> links;  // the links repaired
};

Fixed Fix(const std::string& text, const ReadResult& read) {
  std::vector<Repair> repairs;
  for (const Model& model : read.models) {
    const std::vector<Repair> planned = PlanRepairs(model, CheckModel(model));
    repairs.insert(repairs.end(), planned.begin(), planned.end());
  }
  const PatchResult patched = PatchModelText(text, read.models.front().format, repairs);
  EXPECT_TRUE(patched.errors.empty())
      << patched.errors.front().link << ": " << patched.errors.front().message;
  Fixed fixed{patched.text, patched.applied, {}};
  for (const Repair& r : repairs) fixed.links.insert(r.link);
  return fixed;
}

// (model, link, rule) of every finding of `read`.
std::set<std::tuple<std::string, std::string, std::string>> FindingKeys(const ReadResult& read) {
  std::set<std::tuple<std::string, std::string, std::string>> keys;
  for (const Model& model : read.models) {
    for (const Finding& f : CheckModel(model)) keys.insert({model.name, f.link, f.rule});
  }
  return keys;
}

std::map<std::string, int> remaining_errors;  // rule -> errors left in fixed files

void Count(const ReadResult& read, int* errors, int* warnings, bool fixed = false) {
  for (const Model& model : read.models) {
    for (const Finding& f : CheckModel(model)) {
      if (fixed && f.severity == Severity::kError) ++remaining_errors[f.rule];
      *errors += f.severity == Severity::kError;
      *warnings += f.severity == Severity::kWarning;
    }
  }
}

TEST(CorpusFixTest,
     FixingEveryCorpusFileWithErrorsTouchesOnlyInertialLinesAndLeavesNoFixableError) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/MANIFEST.tsv");
  const std::vector<Entry> entries = ReadManifest();
  std::string pattern = (fs::temp_directory_path() / "massprops-corpus-fix-XXXXXX").string();
  ASSERT_NE(mkdtemp(pattern.data()), nullptr);
  const fs::path out_dir = pattern;
  std::map<std::string, Counts> table;
  int fixed_files = 0;
  for (const Entry& entry : entries) {
    const std::string path = (kCorpus / entry.file).string();
    std::string text;
    if (ReadInputFile(path, kMaxModelFileBytes, &text)) continue;
    const ReadResult read = ReadModelString(text, path);
    if (!read.ok() || read.models.empty()) continue;
    Counts& counts = table[entry.source];
    ++counts.files;
    int errors = 0, warnings = 0;
    Count(read, &errors, &warnings);
    counts.errors_before += errors;
    counts.warnings_before += warnings;
    SCOPED_TRACE(entry.file);
    const Fixed fixed = Fix(text, read);
    // The contract of `fix` without options: only links with an error finding change.
    std::set<std::string> error_links;
    for (const Model& model : read.models) {
      for (const Finding& f : CheckModel(model)) {
        if (f.severity == Severity::kError) error_links.insert(f.link);
      }
    }
    for (const std::string& link : fixed.links) {
      EXPECT_TRUE(error_links.count(link)) << "link '" << link << "' has no error but changed";
    }
    if (errors == 0) {
      EXPECT_EQ(fixed.text, text);
      counts.errors_after += errors;
      counts.warnings_after += warnings;
      continue;
    }
    ++counts.fixed;
    ++fixed_files;
    counts.links_repaired += fixed.repairs;
    const fs::path out =
        out_dir / (std::to_string(fixed_files) + fs::path(entry.file).extension().string());
    std::ofstream(out, std::ios::binary) << fixed.text;

    // Only inertial lines change.
    const LineChanges changes = DiffLines(text, fixed.text);
    const std::vector<bool> old_inertial = InertialLines(text);
    const std::vector<bool> new_inertial = InertialLines(fixed.text);
    for (int line : changes.removed) {
      EXPECT_TRUE(old_inertial.at(line - 1)) << "removed line " << line;
    }
    for (int line : changes.added) EXPECT_TRUE(new_inertial.at(line - 1)) << "added line " << line;

    // Reads back; no error left that a repair exists for.
    const ReadResult after = ReadModelString(fixed.text, path);
    ASSERT_TRUE(after.ok());
    // No finding that the original lacked.
    const auto keys_before = FindingKeys(read);
    for (const auto& key : FindingKeys(after)) {
      EXPECT_TRUE(keys_before.count(key))
          << "new finding " << std::get<2>(key) << " on link '" << std::get<1>(key) << "'";
    }
    int errors_after = 0, warnings_after = 0;
    Count(after, &errors_after, &warnings_after, /*fixed=*/true);
    counts.errors_after += errors_after;
    counts.warnings_after += warnings_after;
    for (const Model& model : after.models) {
      std::vector<Finding> findings = CheckModel(model);
      AttachRepairs(PlanRepairs(model, findings), findings);
      for (const Finding& f : findings) {
        EXPECT_FALSE(f.severity == Severity::kError && f.repair.has_value())
            << f.rule << " " << f.message;
      }
    }
    // Idempotent.
    EXPECT_EQ(Fix(fixed.text, after).text, fixed.text);
  }
  EXPECT_GT(fixed_files, 0);

  std::printf(
      "| source | files | fixed | links repaired | errors before → after | "
      "warnings before → after |\n| --- | --- | --- | --- | --- | --- |\n");
  Counts total;
  for (const auto& [source, c] : table) {
    std::printf("| %s | %d | %d | %d | %d → %d | %d → %d |\n", source.c_str(), c.files, c.fixed,
                c.links_repaired, c.errors_before, c.errors_after, c.warnings_before,
                c.warnings_after);
    total.files += c.files;
    total.fixed += c.fixed;
    total.links_repaired += c.links_repaired;
    total.errors_before += c.errors_before;
    total.errors_after += c.errors_after;
    total.warnings_before += c.warnings_before;
    total.warnings_after += c.warnings_after;
  }
  std::printf("| **total** | %d | %d | %d | %d → %d | %d → %d |\n", total.files, total.fixed,
              total.links_repaired, total.errors_before, total.errors_after, total.warnings_before,
              total.warnings_after);
  for (const auto& [rule, n] : remaining_errors) {
    std::printf("errors left in fixed files: %s %d\n", rule.c_str(), n);
  }
  std::error_code ec;
  fs::remove_all(out_dir, ec);
}

}  // namespace
}  // namespace massprops
