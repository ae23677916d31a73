#pragma once
// The small part of xacro's expression language that inertial numbers are written in: Python
// arithmetic (+ - * / // % **, unary minus, parentheses), numbers, quoted strings, names (looked
// up by the caller), a few math functions (sqrt, sin, cos, tan, atan2, radians, degrees, abs, pow,
// min, max, float, int) and == / != between two values. Anything else (subscripts, attribute
// access, `in`, `if`, lambdas) is not evaluated: the functions return nullopt, never guess.
// Private to src/io (xacro_trace.cc).

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace massprops::xacro {

/// A value of an expression: a number (Python int or float, held as double) or a string.
struct Value {
  bool is_number = false;
  double number = 0;
  std::string text;
};

/// Resolves a name to its value; nullopt when unknown. `$(arg NAME)` is asked as "$(arg NAME)".
using NameLookup = std::function<std::optional<Value>(const std::string& name)>;

/// Evaluates one expression (the text inside `${...}`). Returns nullopt when the expression uses
/// something outside the subset above or a name the lookup does not know, or is longer than
/// 4096 bytes. Never throws.
std::optional<Value> EvaluateExpression(std::string_view expression, const NameLookup& lookup);

/// Evaluates an attribute's text: literal text with `${...}` and `$(arg NAME)` parts, as xacro
/// does (a text that is exactly one `${...}` keeps its value's type; otherwise the parts are
/// joined as strings, numbers printed with 17 significant digits). nullopt when a part cannot be
/// evaluated. `$(find PKG)` is kept as written.
std::optional<Value> EvaluateText(std::string_view text, const NameLookup& lookup);

/// The `${...}` parts of a text (their inside), in order.
std::vector<std::string> ExpressionsOf(std::string_view text);

/// The names an expression reads (identifiers outside quotes that are not called as functions),
/// in order of first use, without duplicates.
std::vector<std::string> NamesOf(std::string_view expression);

/// The text read as a number as xacro reads a property value (Python int() then float():
/// surrounding blanks allowed); nullopt when it is not one number.
std::optional<double> ParseNumber(std::string_view text);

/// The text read as blank-separated numbers (an xyz or rpy attribute); empty when some word is
/// not a number.
std::vector<double> ParseNumbers(std::string_view text);

}  // namespace massprops::xacro
