#pragma once
/// @file
/// The one formatting layer of a finding's parts (its headline, evidence and help; checks.h):
/// numbers at 3 significant digits, lengths below 1 m in mm or cm, ratios written like `577x`,
/// each named number rendered by the SI unit its name ends in; and each rule's long form
/// (`massprops explain RULE`), compiled into the library from docs/rules.md so that the two
/// cannot drift apart. Rules write their headlines with these functions; every reporter renders
/// the parts with them.

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "massprops/analysis/checks.h"

namespace massprops {

/// The most characters of a headline (between `severity: ` and ` [rule]` in text output).
inline constexpr std::size_t kMaxHeadlineChars = 110;
/// The most characters of a line under a headline (`  = evidence: ...`, `  = help: ...`).
inline constexpr std::size_t kMaxDetailChars = 100;

/// `x` with `digits` significant digits, without trailing zeros, the exponent short:
/// 0.009037 → "0.00904", 1234 → "1230" (whole below 1e5), 1234567 → "1.23e6", 2 → "2",
/// -0.5 → "-0.5"; "nan", "inf", "-inf".
std::string FormatSignificant(double x, int digits = 3);
/// A length in metres: below 1 cm in mm, below 1 m in cm, else in m, 3 significant digits:
/// 0.00904 → "9.04 mm", 0.15 → "15 cm", 2.5 → "2.5 m", 0 → "0 mm".
std::string FormatLength(double metres);
/// A ratio as "577x", "1e6x", "0.018x" (3 significant digits).
std::string FormatRatio(double ratio);
/// A mass: "2 kg", "0.15 kg".
std::string FormatMass(double kg);
/// A moment of inertia: "0.0279 kg·m²".
std::string FormatInertia(double kg_m2);
/// The extents of a box as "4 × 4 × 10 cm" (the unit of the largest, 3 significant digits).
std::string FormatExtents(double x_m, double y_m, double z_m);

/// The value of a named number, by the unit its name ends in: `_kg_m2` kg·m², `_kg_m3` kg/m³,
/// `_m3` m³, `_m2` m², `_kg` kg, `_n_m` N·m (a joint torque), `_m` a length (FormatLength), `_rad` rad, `_deg` °, `_percent`
/// %, `ratio` / `_ratio` a ratio (FormatRatio), `_count` an integer; anything else a plain number.
std::string FormatEvidenceValue(std::string_view name, double value);
/// The name without its unit, underscores as spaces, the word "com" as "COM": the words a robot
/// engineer reads without the docs, so each name says what it is in full
/// ("radius_of_gyration_m", not "k_m"): "half_diagonal_m" → "half diagonal", "com_x_m" →
/// "COM x", "ratio" → "ratio".
std::string EvidenceLabel(std::string_view name);
/// Each named number as "mass 2 kg", "half diagonal 21.2 cm", "ratio 0.018x", in order.
std::vector<std::string> EvidenceItems(const std::vector<std::pair<std::string, double>>& evidence);
/// "mass 2 kg, half diagonal 21.2 cm, ratio 0.018x": every item, never cut; on one line by
/// default (the HTML view), else the lines of FormatEvidenceLines joined by "\n".
std::string FormatEvidence(const std::vector<std::pair<std::string, double>>& evidence,
                           std::size_t max_chars = std::string::npos);
/// The evidence as whole lines of at most `max_chars` characters (JoinIntoLines of its items):
/// text output's `  = evidence: ...` lines, one per element, never cut. The default leaves room
/// for "  = evidence: " within kMaxDetailChars.
std::vector<std::string> FormatEvidenceLines(
    const std::vector<std::pair<std::string, double>>& evidence,
    std::size_t max_chars = kMaxDetailChars - 14);
/// `items` joined by ", " into lines of at most `max_chars` characters, in order, as many items
/// on a line as fit; no item is ever cut: one longer than `max_chars` stands alone on its line.
/// {} for no items. ["a", "bb", "cc"] in 6 → ["a, bb", "cc"].
std::vector<std::string> JoinIntoLines(const std::vector<std::string>& items,
                                       std::size_t max_chars);

/// The characters of UTF-8 text (not its bytes: "·", "²" and "×" take two bytes each).
std::size_t CountChars(std::string_view text);

/// A headline is a whole sentence of at most kMaxHeadlineChars characters, never cut: where a
/// name would make it longer, a shorter sentence is written instead. `before` + "link 'NAME'" +
/// `after` (`after` like ": inertia 5x too large for its 15 cm box (mass changed?)" or " has no
/// <inertial>") when it fits; else the same sentence about "this link" (text output's file:line
/// and JSON's `link` name it), however long the name.
std::string LinkHeadline(std::string_view name, std::string_view after,
                         std::string_view before = "");
/// "link 'NAME'" + the first of `afters` (the fullest first) with which the sentence fits; else
/// "this link" + the last of them.
std::string LinkHeadlineFirstFit(std::string_view name, std::initializer_list<std::string> afters);
/// As LinkHeadline, about a model: "model 'NAME'", else "this model".
std::string ModelHeadline(std::string_view name, std::string_view after,
                          std::string_view before = "");
/// The first of `sentences` (whole headlines, the fullest first) that has at most
/// kMaxHeadlineChars characters; the last one when none does (its author makes it short).
std::string FirstThatFits(std::initializer_list<std::string> sentences);
/// A headline made of `text` (a reader's message: "what is wrong; what follows from it"), never
/// cutting a word or a name: the text itself when it fits kMaxHeadlineChars; else its leading
/// clauses up to a "; " that fit (each clause a sentence of its own); else the same of the text
/// without its parenthetical remarks " (...)"; else its lead up to the first ": " (the element
/// or the subject) followed by ": " and `more`; else `fallback`, a whole sentence. "" for "".
std::string HeadlineFromMessage(std::string_view text, std::string_view fallback,
                                std::string_view more = "the full message says more");

/// The longest lead of `text` up to a ": " (the most specific details dropped from the end), its
/// parenthetical remarks left out, that fits kMaxHeadlineChars; "" when none does. "link 'a':
/// mesh cannot be used: mesh file 'g.stl' cannot be read: Failed to determine ..." → "link 'a':
/// mesh cannot be used: mesh file 'g.stl' cannot be read".
std::string LongestLeadThatFits(std::string_view text);

/// The finding's headline, or a headline made of its message (HeadlineFromMessage) when the
/// rule gave none (a Finding made by other code); at most kMaxHeadlineChars characters when
/// the rule kept to it. Never empty when either is set.
std::string HeadlineOf(const Finding& finding);

/// The long form of `rule` (what it means, the physics and the evidence it reads, an example,
/// how to fix and silence it): its section of docs/rules.md, as compiled into the library.
/// nullopt for a rule docs/rules.md does not document.
std::optional<std::string> RuleLongForm(std::string_view rule);
/// The rules that have a long form, in the order of docs/rules.md.
std::vector<std::string> RulesWithLongForm();

}  // namespace massprops
