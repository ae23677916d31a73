// Headlines on the whole corpus (issue 43): every finding's and every read error's headline is a
// whole sentence of at most kMaxHeadlineChars characters, never cut ("…" never appears in one),
// in text (between `severity: ` and ` [rule]`), JSON (`headline` of findings and errors) and
// SARIF (`message.text`). Run as tools/label_score.py and tools/finding_lengths.py run the tool:
// from ../shared/corpus, with `--package-path .` and the corpus's model folders, on every URDF
// and SDF of its MANIFEST. The unit tests of the shorter sentences (long names) are in
// finding_text_test.cc and reporters_test.cc.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "corpus_manifest.h"
#include "massprops/analysis/finding_text.h"

namespace {

using massprops::CountChars;
using massprops::kMaxHeadlineChars;
using massprops::test_support::CorpusDir;
using massprops::test_support::ManifestRow;
using massprops::test_support::ReadCorpusManifest;

std::string Quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// `cd CORPUS && massprops check ARGS FILES...` as tools/label_score.py runs it; standard output.
std::string CheckCorpus(const std::string& args) {
  std::string command = "cd " + Quote(CorpusDir()) + " && " + Quote(MASSPROPS_TOOL_PATH) +
                        " check -j 2 --package-path . " + args;
  for (const std::string& folder : massprops::test_support::CorpusModelFolders()) {
    command += " --model-path " + folder;
  }
  for (const ManifestRow& row : ReadCorpusManifest()) {
    if (row.format == "urdf" || row.format == "sdf") command += " " + Quote(row.file);
  }
  command += " 2>/dev/null";
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return output;
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) output.append(buffer, n);
  pclose(pipe);
  return output;
}

// The corpus's output in the three formats, computed once for all the tests.
struct CorpusOutputs {
  std::string text, json, sarif;
};

const CorpusOutputs& Outputs() {
  static const CorpusOutputs outputs = [] {
    CorpusOutputs o;
    o.text = CheckCorpus("--color never");
    o.json = CheckCorpus("--format json");
    o.sarif = CheckCorpus("--format sarif");
    return o;
  }();
  return outputs;
}

// What is wrong with a headline: "" when it is whole and short enough.
std::string Fault(const std::string& headline) {
  if (headline.empty()) return "empty";
  if (headline.find("\u2026") != std::string::npos) return "cut (contains …)";
  if (CountChars(headline) > kMaxHeadlineChars) {
    return std::to_string(CountChars(headline)) + " characters";
  }
  return "";
}

// The (headline, rule) of each line `file:line[:col]: severity: HEADLINE [rule]` of the text
// output (the xacro source note may follow the rule).
std::vector<std::pair<std::string, std::string>> TextHeadlines() {
  const std::regex line_form(R"(^(\S.*?): (error|warning|note): (.*) \[([a-z0-9-]+)\]( \(.*\))?$)");
  std::vector<std::pair<std::string, std::string>> headlines;
  std::istringstream lines(Outputs().text);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (std::regex_match(line, m, line_form)) headlines.emplace_back(m[3], m[4]);
  }
  return headlines;
}

TEST(HeadlineFormTest, TextHeadlinesOfTheCorpusAreWholeAndWithin110Characters) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/MANIFEST.tsv");
  std::size_t read_errors = 0;
  const auto headlines = TextHeadlines();
  for (const auto& [headline, rule] : headlines) {
    read_errors += rule == "read-error";
    EXPECT_EQ(Fault(headline), "") << headline << " [" << rule << "]";
  }
  // The corpus gives hundreds of findings (tools/finding_lengths.py counts them) and some files
  // that do not read: a handful of headlines would make the test weak.
  EXPECT_GE(headlines.size(), 300u);
  EXPECT_GE(read_errors, 1u);
}

TEST(HeadlineFormTest, JsonHeadlinesOfFindingsAndReadErrorsAreWholeAndWithin110Characters) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/MANIFEST.tsv");
  const nlohmann::json doc = nlohmann::json::parse(Outputs().json);
  std::size_t findings = 0, errors = 0;
  for (const auto& file : doc.at("files")) {
    for (const auto& finding : file.at("findings")) {
      ++findings;
      EXPECT_EQ(Fault(finding.at("headline")), "") << finding.dump();
    }
    for (const auto& error : file.at("errors")) {
      ++errors;
      EXPECT_EQ(Fault(error.at("headline")), "") << error.dump();
    }
  }
  EXPECT_GE(findings, 300u);
  EXPECT_GE(errors, 1u);
  // The text lists the same findings and read errors, one headline each.
  EXPECT_EQ(TextHeadlines().size(), findings + errors);
}

TEST(HeadlineFormTest, SarifMessagesOfTheCorpusAreWholeAndWithin110Characters) {
  MASSPROPS_SKIP_WITHOUT_SHARED("corpus/MANIFEST.tsv");
  const nlohmann::json log = nlohmann::json::parse(Outputs().sarif);
  std::size_t results = 0;
  for (const auto& result : log.at("runs").at(0).at("results")) {
    ++results;
    EXPECT_EQ(Fault(result.at("message").at("text")), "") << result.at("ruleId");
  }
  EXPECT_GE(results, 300u);
}

}  // namespace
