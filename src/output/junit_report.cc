// `massprops check --format junit` (reporters.h, RenderJunit; docs/cli.md): JUnit XML in the shape
// colcon test-result, GitLab's unit-test report and Jenkins' junit step read.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "massprops/analysis/finding_text.h"
#include "massprops/output/reporters.h"
#include "output/report_place.h"

namespace massprops {
namespace {

using internal::PlaceOf;
using internal::ReportedFile;
using internal::ReportPlace;

// The length of the UTF-8 sequence that starts at text[at] and the code point it encodes, or 0
// when the bytes there are not a well-formed sequence (RFC 3629: no overlong forms, no
// surrogates, nothing above U+10FFFF).
std::size_t Utf8Sequence(std::string_view text, std::size_t at, std::uint32_t* code_point) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(at);
  if (lead < 0x80) {
    *code_point = lead;
    return 1;
  }
  // The sequence's length, the lead byte's payload bits, and the smallest code point that needs
  // this many bytes.
  std::size_t length = 4;
  std::uint32_t cp = lead & 0x07u, min = 0x10000;
  if ((lead & 0xE0) == 0xC0) {
    length = 2;
    cp = lead & 0x1Fu;
    min = 0x80;
  } else if ((lead & 0xF0) == 0xE0) {
    length = 3;
    cp = lead & 0x0Fu;
    min = 0x800;
  } else if ((lead & 0xF8) != 0xF0) {
    return 0;  // a continuation byte, or 0xF8-0xFF
  }
  if (at + length > text.size()) return 0;
  for (std::size_t i = 1; i < length; ++i) {
    if ((byte(at + i) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (byte(at + i) & 0x3Fu);
  }
  if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  *code_point = cp;
  return length;
}

// Whether XML 1.0 allows the character (its Char production; \t, \n and \r only among the C0
// controls).
bool XmlChar(std::uint32_t cp) {
  return cp == 0x9 || cp == 0xA || cp == 0xD || (cp >= 0x20 && cp <= 0xD7FF) ||
         (cp >= 0xE000 && cp <= 0xFFFD) || (cp >= 0x10000 && cp <= 0x10FFFF);
}

// `text` escaped for XML character data and attribute values (& < > " '; in an attribute also
// \t \n \r as character references, which a parser would otherwise normalise to spaces); bytes
// that are not well-formed UTF-8 and characters XML cannot hold become U+FFFD.
std::string XmlEscape(std::string_view text, bool attribute) {
  std::string out;
  out.reserve(text.size());
  std::size_t at = 0;
  while (at < text.size()) {
    std::uint32_t cp = 0;
    const std::size_t length = Utf8Sequence(text, at, &cp);
    if (length == 0 || !XmlChar(cp)) {
      out += "\xEF\xBF\xBD";  // U+FFFD
      at += length == 0 ? 1 : length;
      continue;
    }
    switch (cp) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += attribute ? "&quot;" : "\"";
        break;
      case '\'':
        out += attribute ? "&apos;" : "'";
        break;
      case '\t':
        out += attribute ? "&#9;" : "\t";
        break;
      case '\n':
        out += attribute ? "&#10;" : "\n";
        break;
      case '\r':  // a parser would turn a literal CR into LF (XML 1.0, 2.11)
        out += "&#13;";
        break;
      default:
        out.append(text.substr(at, length));
    }
    at += length;
  }
  return out;
}

std::string Attribute(const char* name, std::string_view value) {
  return std::string(" ") + name + "=\"" + XmlEscape(value, true) + "\"";
}

std::string FileLine(const ReportPlace& place) {
  return place.line > 0 ? place.file + ":" + std::to_string(place.line) : place.file;
}

// A testcase's class: "massprops." and the model's name, else the checked file's name.
std::string ClassName(const std::string& model, const FileResult& result) {
  if (!model.empty()) return "massprops." + model;
  const std::size_t slash = result.path.find_last_of('/');
  return "massprops." + (slash == std::string::npos ? result.path : result.path.substr(slash + 1));
}

// "RULE: LINK" (the model, else the file, when the finding names no link).
std::string TestName(const Finding& finding, const FileResult& result) {
  const std::string& subject = !finding.link.empty()    ? finding.link
                               : !finding.model.empty() ? finding.model
                                                        : result.path;
  return finding.rule + ": " + subject;
}

// A finding's text: `FILE:LINE: SEVERITY: HEADLINE [RULE]`, then its evidence, its help, a welded
// group's members and, when it was traced to xacro sources, the generated line.
std::string FindingText(const Finding& finding, const FileResult& result) {
  std::string text = FileLine(PlaceOf(finding, result)) + ": " + ToString(finding.severity) + ": " +
                     HeadlineOf(finding) + " [" + finding.rule + "]\n";
  for (const std::string& line : FormatEvidenceLines(finding.evidence)) {
    text += "evidence: " + line + "\n";
  }
  if (!finding.help.empty()) text += "help: " + finding.help + "\n";
  if (!finding.group.empty()) {
    text += "welded group of " + std::to_string(finding.group.size()) + " links:";
    for (std::size_t i = 0; i < finding.group.size(); ++i) {
      text += (i ? ", " : " ") + finding.group[i];
    }
    text += "\n";
  }
  if (finding.source && !finding.source->places.empty()) {
    const SourceLocation& generated = finding.source->generated;
    text += "generated: " + FileLine({generated.file, generated.line}) + " (" +
            finding.source->number + ")\n";
  }
  return ShortenLongWords(text);
}

std::string TestcaseOpen(const std::string& name, const std::string& classname,
                         const ReportPlace& place) {
  std::string out = "    <testcase" + Attribute("name", ShortenLongWords(name)) +
                    Attribute("classname", ShortenLongWords(classname)) +
                    Attribute("file", place.file);
  if (place.line > 0) out += Attribute("line", std::to_string(place.line));
  return out + " time=\"0\"";
}

// One file's <testsuite> element, counting into the totals.
struct SuiteCounts {
  int tests = 0, failures = 0, errors = 0;
};

std::string Testsuite(const FileResult& result, SuiteCounts* totals) {
  SuiteCounts counts;
  std::string cases;
  const std::string file_class = ClassName("", result);
  for (const ReadError& error : result.errors) {
    const ReportPlace place{ReportedFile(error.location, result), error.location.line};
    const std::string what =
        error.element.empty() ? error.message : error.element + ": " + error.message;
    cases += TestcaseOpen(std::string(kReadErrorRule) + ": " +
                              (error.element.empty() ? result.path : error.element),
                          file_class, place) +
             ">\n      <error" + Attribute("message", ShortenLongWords(ReadErrorHeadline(error))) +
             Attribute("type", kReadErrorRule) + ">" +
             XmlEscape(ShortenLongWords(FileLine(place) + ": error: " + ReadErrorHeadline(error) +
                                        "\nwhy: " + what + "\n"),
                       false) +
             "</error>\n    </testcase>\n";
    ++counts.tests, ++counts.errors;
  }
  for (const Finding& finding : result.findings) {
    const std::string text = XmlEscape(FindingText(finding, result), false);
    cases += TestcaseOpen(TestName(finding, result), ClassName(finding.model, result),
                          PlaceOf(finding, result));
    if (finding.severity >= result.fail_on) {
      cases += ">\n      <failure" + Attribute("message", ShortenLongWords(HeadlineOf(finding))) +
               Attribute("type", finding.rule) + ">" + text + "</failure>\n    </testcase>\n";
      ++counts.failures;
    } else {
      // Below the fail level: seen in the test's output, failing nothing.
      cases += ">\n      <system-out>" + text + "</system-out>\n    </testcase>\n";
    }
    ++counts.tests;
  }
  if (counts.tests == 0) {
    const std::string model_class =
        result.models.empty() ? file_class : ClassName(result.models.front(), result);
    cases += TestcaseOpen("massprops check", model_class, {result.path, 0}) + "/>\n";
    ++counts.tests;
  }
  totals->tests += counts.tests;
  totals->failures += counts.failures;
  totals->errors += counts.errors;
  return "  <testsuite" + Attribute("name", ShortenLongWords(result.path)) +
         Attribute("tests", std::to_string(counts.tests)) +
         Attribute("failures", std::to_string(counts.failures)) +
         Attribute("errors", std::to_string(counts.errors)) + " skipped=\"0\" time=\"0\">\n" +
         cases + "  </testsuite>\n";
}

}  // namespace

std::string RenderJunit(const std::vector<FileResult>& results, const ReportOptions& options) {
  (void)options;
  SuiteCounts totals;
  std::string suites;
  for (const FileResult& result : results) suites += Testsuite(result, &totals);
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"massprops check\"" +
         Attribute("tests", std::to_string(totals.tests)) +
         Attribute("failures", std::to_string(totals.failures)) +
         Attribute("errors", std::to_string(totals.errors)) + " skipped=\"0\" time=\"0\">\n" +
         suites + "</testsuites>\n";
}

}  // namespace massprops
