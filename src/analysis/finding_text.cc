#include "massprops/analysis/finding_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

#include "massprops/core/format_number.h"

namespace massprops {

namespace detail {
// docs/rules.md as it was when the library was built (generated from cmake/rules_md.cc.in).
extern const char* const kRulesMarkdown;
}  // namespace detail

namespace {

bool EndsWith(std::string_view text, std::string_view tail) {
  return text.size() >= tail.size() && text.substr(text.size() - tail.size()) == tail;
}

// The units a name may end in, longest first, with how the value is written.
enum class Unit {
  kInertia,
  kDensity,
  kVolume,
  kArea,
  kMass,
  kLength,
  kRadian,
  kDegree,
  kPercent,
  kRatio,
  kCount,
  kTorque,
  kNone
};

struct UnitSuffix {
  const char* suffix;
  Unit unit;
};

constexpr UnitSuffix kSuffixes[] = {
    {"_kg_m2", Unit::kInertia},   {"_kg_m3", Unit::kDensity}, {"_m3", Unit::kVolume},
    {"_m2", Unit::kArea},         {"_kg", Unit::kMass},       {"_n_m", Unit::kTorque},
    {"_m", Unit::kLength},        {"_rad", Unit::kRadian},    {"_deg", Unit::kDegree},
    {"_percent", Unit::kPercent}, {"_ratio", Unit::kRatio},   {"_count", Unit::kCount}};

// The unit of `name` and the length of its suffix.
std::pair<Unit, std::size_t> UnitOf(std::string_view name) {
  if (name == "ratio") return {Unit::kRatio, name.size()};
  for (const UnitSuffix& s : kSuffixes) {
    if (EndsWith(name, s.suffix) && name.size() > std::string_view(s.suffix).size()) {
      return {s.unit, std::string_view(s.suffix).size()};
    }
  }
  return {Unit::kNone, 0};
}

// A line that starts a section of docs/rules.md, and its level (3 or 4) and rule; level 0 when
// the line is no rule's heading; level 1 or 2 for "#" and "##" headings (they end a section).
std::pair<int, std::string> Heading(std::string_view line) {
  int level = 0;
  while (level < static_cast<int>(line.size()) && line[level] == '#') ++level;
  if (level == 0 || level >= static_cast<int>(line.size()) || line[level] != ' ') return {0, ""};
  if (level <= 2) return {level, ""};
  std::string_view rest = line.substr(level + 1);
  if (rest.empty() || rest[0] != '`') return {level, ""};
  const std::size_t close = rest.find('`', 1);
  if (close == std::string_view::npos) return {level, ""};
  return {level, std::string(rest.substr(1, close - 1))};
}

// Each rule's section of docs/rules.md: (rule, text), in order.
std::vector<std::pair<std::string, std::string>> Sections() {
  std::vector<std::pair<std::string, std::string>> sections;
  const std::string_view text = detail::kRulesMarkdown;
  bool in_code = false;
  int open_level = 0;  // the level of the section being collected; 0 when none
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    if (line.rfind("```", 0) == 0) in_code = !in_code;
    const auto [level, rule] = in_code ? std::pair<int, std::string>{0, ""} : Heading(line);
    if (level > 0 && open_level > 0 && level <= open_level) open_level = 0;
    if (level >= 3 && !rule.empty()) {
      sections.emplace_back(rule, "");
      open_level = level;
    }
    if (open_level > 0) sections.back().second.append(line).append("\n");
    start = end + 1;
  }
  for (auto& [rule, body] : sections) {
    while (!body.empty() && (body.back() == '\n' || body.back() == ' ')) body.pop_back();
    body += '\n';
  }
  return sections;
}

}  // namespace

std::string FormatSignificant(double x, int digits) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  std::string text = FormatPrecision(x, digits);  // printf's "%.*g"
  // Below 1e5, a whole number reads better than an exponent: 1234 → "1230", not "1.23e3".
  double rounded = 0;
  std::from_chars(text.data(), text.data() + text.size(), rounded);
  if (std::abs(rounded) >= 1000 && std::abs(rounded) < 1e5) {
    char buffer[32];  // printf's "%.0f" of a number below 1e5
    const std::to_chars_result r =
        std::to_chars(buffer, buffer + sizeof buffer, rounded, std::chars_format::fixed, 0);
    return std::string(buffer, r.ptr);
  }
  // "1e+06" → "1e6", "1.5e-05" → "1.5e-5".
  const std::size_t e = text.find('e');
  if (e != std::string::npos) {
    std::string mantissa = text.substr(0, e);
    std::string exponent = text.substr(e + 1);
    std::string sign;
    if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-')) {
      if (exponent[0] == '-') sign = "-";
      exponent.erase(0, 1);
    }
    exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
    text = mantissa + "e" + sign + exponent;
  }
  return text;
}

std::string FormatLength(double metres) {
  if (!std::isfinite(metres)) return FormatSignificant(metres) + " m";
  const double a = std::abs(metres);
  // Rounded to 3 digits first, so that 0.99996 m is "1 m", not "100 cm".
  const double rounded = std::stod(FormatSignificant(a));
  if (rounded < 0.01) return FormatSignificant(metres * 1000) + " mm";
  if (rounded < 1) return FormatSignificant(metres * 100) + " cm";
  return FormatSignificant(metres) + " m";
}

std::string FormatRatio(double ratio) { return FormatSignificant(ratio) + "x"; }

std::string FormatMass(double kg) { return FormatSignificant(kg) + " kg"; }

std::string FormatInertia(double kg_m2) { return FormatSignificant(kg_m2) + " kg·m²"; }

std::string FormatExtents(double x_m, double y_m, double z_m) {
  const double largest = std::max({std::abs(x_m), std::abs(y_m), std::abs(z_m)});
  const std::string unit_of_largest = FormatLength(largest);
  const std::string unit = unit_of_largest.substr(unit_of_largest.rfind(' ') + 1);
  const double scale = unit == "mm" ? 1000 : unit == "cm" ? 100 : 1;
  return FormatSignificant(x_m * scale) + " × " + FormatSignificant(y_m * scale) + " × " +
         FormatSignificant(z_m * scale) + " " + unit;
}

std::string FormatEvidenceValue(std::string_view name, double value) {
  switch (UnitOf(name).first) {
    case Unit::kInertia:
      return FormatInertia(value);
    case Unit::kDensity:
      return FormatSignificant(value) + " kg/m³";
    case Unit::kVolume:
      return FormatSignificant(value) + " m³";
    case Unit::kArea:
      return FormatSignificant(value) + " m²";
    case Unit::kMass:
      return FormatMass(value);
    case Unit::kLength:
      return FormatLength(value);
    case Unit::kRadian:
      return FormatSignificant(value) + " rad";
    case Unit::kDegree:
      return FormatSignificant(value) + "°";
    case Unit::kPercent:
      return FormatSignificant(value) + "%";
    case Unit::kRatio:
      return FormatRatio(value);
    case Unit::kCount:
      return std::isfinite(value) ? std::to_string(static_cast<long long>(std::llround(value)))
                                  : FormatSignificant(value);
    case Unit::kTorque:  // joint torque (N·m; the force of a prismatic joint in N shares it)
      return FormatSignificant(value) + " N·m";
    case Unit::kNone:
      break;
  }
  return FormatSignificant(value);
}

std::string EvidenceLabel(std::string_view name) {
  const std::size_t suffix = UnitOf(name).second;
  std::string label(name == "ratio" ? name : name.substr(0, name.size() - suffix));
  std::replace(label.begin(), label.end(), '_', ' ');
  // The center of mass is "COM" as robot engineers write it: "com x" → "COM x".
  for (std::size_t at = label.find("com"); at != std::string::npos;
       at = label.find("com", at + 3)) {
    const bool starts = at == 0 || label[at - 1] == ' ';
    const bool ends = at + 3 == label.size() || label[at + 3] == ' ';
    if (starts && ends) label.replace(at, 3, "COM");
  }
  return label;
}

std::vector<std::string> EvidenceItems(
    const std::vector<std::pair<std::string, double>>& evidence) {
  std::vector<std::string> items;
  items.reserve(evidence.size());
  for (const auto& [name, value] : evidence) {
    items.push_back(EvidenceLabel(name) + " " + FormatEvidenceValue(name, value));
  }
  return items;
}

std::string FormatEvidence(const std::vector<std::pair<std::string, double>>& evidence,
                           std::size_t max_chars) {
  std::string out;
  for (const std::string& line : FormatEvidenceLines(evidence, max_chars)) {
    out += (out.empty() ? "" : "\n") + line;
  }
  return out;
}

std::vector<std::string> FormatEvidenceLines(
    const std::vector<std::pair<std::string, double>>& evidence, std::size_t max_chars) {
  return JoinIntoLines(EvidenceItems(evidence), max_chars);
}

std::vector<std::string> JoinIntoLines(const std::vector<std::string>& items,
                                       std::size_t max_chars) {
  std::vector<std::string> lines;
  std::size_t chars = 0;  // of lines.back(), counted in characters ("·", "²" take two bytes)
  for (const std::string& item : items) {
    const std::size_t item_chars = CountChars(item);
    if (!lines.empty() && chars + 2 + item_chars <= max_chars) {
      lines.back().append(", ").append(item);
      chars += 2 + item_chars;
    } else {
      lines.push_back(item);
      chars = item_chars;
    }
  }
  return lines;
}

std::size_t CountChars(std::string_view text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

namespace {

std::string WithoutParentheses(std::string_view text);

// `before` + `kind` 'NAME' + `after` when it fits a headline; else the same without the
// parenthetical remarks of `after` (the cause guessed, which the help repeats), the name being
// what tells the links apart; else `before` + "this " + `kind` + `after`.
std::string NamedHeadline(std::string_view kind, std::string_view name, std::string_view after,
                          std::string_view before) {
  std::string named(before);
  named.append(kind).append(" '").append(name).append("'");
  if (CountChars(named) + CountChars(after) <= kMaxHeadlineChars) return named.append(after);
  const std::string plain = WithoutParentheses(after);
  if (CountChars(named) + CountChars(plain) <= kMaxHeadlineChars) return named.append(plain);
  std::string unnamed(before);
  unnamed.append("this ").append(kind).append(after);
  return unnamed;
}

}  // namespace

std::string LinkHeadline(std::string_view name, std::string_view after, std::string_view before) {
  return NamedHeadline("link", name, after, before);
}

std::string LinkHeadlineFirstFit(std::string_view name, std::initializer_list<std::string> afters) {
  std::string last;
  for (const std::string& after : afters) {
    std::string named = "link '";
    named.append(name).append("'").append(after);
    if (CountChars(named) <= kMaxHeadlineChars) return named;
    last = after;
  }
  return "this link" + last;
}

std::string ModelHeadline(std::string_view name, std::string_view after, std::string_view before) {
  return NamedHeadline("model", name, after, before);
}

std::string FirstThatFits(std::initializer_list<std::string> sentences) {
  std::string last;
  for (const std::string& sentence : sentences) {
    if (CountChars(sentence) <= kMaxHeadlineChars) return sentence;
    last = sentence;
  }
  return last;
}

namespace {

// `text` without its parenthetical remarks (" (...)", nested ones too): a sentence stays whole
// without them. An unclosed "(" is kept with the rest.
std::string WithoutParentheses(std::string_view text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text.compare(i, 2, " (") == 0) {
      int depth = 0;
      std::size_t j = i + 1;
      for (; j < text.size(); ++j) {
        if (text[j] == '(') ++depth;
        if (text[j] == ')' && --depth == 0) break;
      }
      if (j < text.size()) {
        i = j + 1;
        continue;
      }
    }
    out += text[i++];
  }
  return out;
}

// The longest run of leading clauses of `text` (joined by "; ", each a sentence of its own) that
// fits a headline; "" when even the first does not.
std::string LeadingClauses(std::string_view text) {
  if (CountChars(text) <= kMaxHeadlineChars) return std::string(text);
  std::size_t best = std::string_view::npos;
  for (std::size_t at = text.find("; "); at != std::string_view::npos;
       at = text.find("; ", at + 2)) {
    if (CountChars(text.substr(0, at)) > kMaxHeadlineChars) break;
    best = at;
  }
  return best == std::string_view::npos ? "" : std::string(text.substr(0, best));
}

}  // namespace

std::string HeadlineFromMessage(std::string_view text, std::string_view fallback,
                                std::string_view more) {
  if (text.empty()) return "";
  std::string headline = LeadingClauses(text);
  if (!headline.empty()) return headline;
  const std::string plain = WithoutParentheses(text);
  headline = LeadingClauses(plain);
  if (!headline.empty()) return headline;
  // The lead up to the first ": " (the element or the subject: what the rest details), then
  // `more`.
  const std::size_t lead = plain.find(": ");
  if (lead != std::string::npos && lead > 0 &&
      CountChars(plain.substr(0, lead)) + 2 + CountChars(more) <= kMaxHeadlineChars) {
    return plain.substr(0, lead) + ": " + std::string(more);
  }
  return std::string(fallback);
}

std::string LongestLeadThatFits(std::string_view text) {
  const std::string plain = WithoutParentheses(text);
  std::size_t best = std::string::npos;
  for (std::size_t at = plain.find(": "); at != std::string::npos; at = plain.find(": ", at + 2)) {
    if (CountChars(plain.substr(0, at)) > kMaxHeadlineChars) break;
    best = at;
  }
  return best == std::string::npos ? "" : plain.substr(0, best);
}

std::string HeadlineOf(const Finding& finding) {
  const std::string& text = finding.headline.empty() ? finding.message : finding.headline;
  return HeadlineFromMessage(text, "this finding's message is too long for a headline (--explain)",
                             "--explain gives the whole message");
}

std::optional<std::string> RuleLongForm(std::string_view rule) {
  for (const auto& [id, text] : Sections()) {
    if (id == rule) return text;
  }
  return std::nullopt;
}

std::vector<std::string> RulesWithLongForm() {
  std::vector<std::string> rules;
  for (const auto& [id, text] : Sections()) rules.push_back(id);
  return rules;
}

}  // namespace massprops
