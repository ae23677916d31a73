#include "io/xacro_eval.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace massprops::xacro {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxDepth = 64;  // nesting of parentheses and unary operators
constexpr std::size_t kMaxExpressionBytes = 4096;

bool IsIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool IsIdentChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
}

// A recursive-descent reader of the subset (see the header). Every method returns nullopt on
// anything it does not understand; `ok_` turns false then and stays false.
class Parser {
 public:
  Parser(std::string_view text, const NameLookup& lookup) : s_(text), lookup_(lookup) {}

  std::optional<Value> Run() {
    std::optional<Value> value = Comparison();
    Skip();
    if (!value || pos_ != s_.size()) return std::nullopt;
    return value;
  }

 private:
  void Skip() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  bool Eat(std::string_view token) {
    Skip();
    if (s_.substr(pos_, token.size()) != token) return false;
    pos_ += token.size();
    return true;
  }
  bool Peek(std::string_view token) {
    Skip();
    return s_.substr(pos_, token.size()) == token;
  }

  std::optional<Value> Comparison() {
    std::optional<Value> left = Sum();
    if (!left) return std::nullopt;
    const bool eq = Peek("=="), ne = Peek("!=");
    if (!eq && !ne) return left;
    pos_ += 2;
    std::optional<Value> right = Sum();
    if (!right) return std::nullopt;
    bool same = false;
    if (left->is_number && right->is_number) {
      same = left->number == right->number;
    } else if (!left->is_number && !right->is_number) {
      same = left->text == right->text;
    }
    Value out;
    out.is_number = true;
    out.number = (eq ? same : !same) ? 1 : 0;
    return out;
  }

  std::optional<Value> Sum() {
    std::optional<Value> left = Product();
    while (left) {
      if (Peek("+")) {
        ++pos_;
        std::optional<Value> right = Product();
        if (!right) return std::nullopt;
        if (left->is_number && right->is_number) {
          left->number += right->number;
        } else if (!left->is_number && !right->is_number) {
          left->text += right->text;
        } else {
          return std::nullopt;
        }
      } else if (Peek("-")) {
        ++pos_;
        std::optional<Value> right = Product();
        if (!right || !left->is_number || !right->is_number) return std::nullopt;
        left->number -= right->number;
      } else {
        break;
      }
    }
    return left;
  }

  std::optional<Value> Product() {
    std::optional<Value> left = Unary();
    while (left) {
      Skip();
      if (Peek("**")) break;  // handled in Power
      char op = 0;
      bool floor_div = false;
      if (Peek("//")) {
        op = '/';
        floor_div = true;
        pos_ += 2;
      } else if (Peek("*") || Peek("/") || Peek("%")) {
        op = s_[pos_++];
      } else {
        break;
      }
      std::optional<Value> right = Unary();
      if (!right || !left->is_number || !right->is_number) return std::nullopt;
      if ((op == '/' || op == '%') && right->number == 0) return std::nullopt;  // Python raises
      if (op == '*') left->number *= right->number;
      if (op == '/') {
        left->number /= right->number;
        if (floor_div) left->number = std::floor(left->number);
      }
      if (op == '%') {
        const double r = std::fmod(left->number, right->number);
        left->number = (r != 0 && ((r < 0) != (right->number < 0))) ? r + right->number : r;
      }
    }
    return left;
  }

  std::optional<Value> Unary() {
    if (++depth_ > kMaxDepth) return std::nullopt;
    std::optional<Value> out;
    if (Peek("-") && !Peek("-=")) {
      ++pos_;
      out = Unary();
      if (out && out->is_number) {
        out->number = -out->number;
      } else {
        out.reset();
      }
    } else if (Peek("+")) {
      ++pos_;
      out = Unary();
      if (out && !out->is_number) out.reset();
    } else {
      out = Power();
    }
    --depth_;
    return out;
  }

  std::optional<Value> Power() {
    std::optional<Value> base = Atom();
    if (!base || !Peek("**")) return base;
    pos_ += 2;
    std::optional<Value> exponent = Unary();  // right-associative, binds a unary minus
    if (!exponent || !base->is_number || !exponent->is_number) return std::nullopt;
    base->number = std::pow(base->number, exponent->number);
    return base;
  }

  std::optional<Value> Atom() {
    Skip();
    if (pos_ >= s_.size()) return std::nullopt;
    const char c = s_[pos_];
    if (c == '(') {
      ++pos_;
      if (++depth_ > kMaxDepth) return std::nullopt;
      std::optional<Value> inner = Comparison();
      --depth_;
      if (!inner || !Eat(")")) return std::nullopt;
      return inner;
    }
    if (c == '\'' || c == '"') {
      const std::size_t end = s_.find(c, pos_ + 1);
      if (end == std::string_view::npos) return std::nullopt;
      Value out;
      out.text = std::string(s_.substr(pos_ + 1, end - pos_ - 1));
      pos_ = end + 1;
      return out;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      const std::string rest(s_.substr(pos_));
      char* end = nullptr;
      const double number = std::strtod(rest.c_str(), &end);
      if (end == rest.c_str()) return std::nullopt;
      pos_ += static_cast<std::size_t>(end - rest.c_str());
      Value out;
      out.is_number = true;
      out.number = number;
      return out;
    }
    if (IsIdentStart(c)) {
      const std::size_t start = pos_;
      while (pos_ < s_.size() && IsIdentChar(s_[pos_])) ++pos_;
      std::string name(s_.substr(start, pos_ - start));
      if (name.rfind("math.", 0) == 0) name = name.substr(5);
      if (Peek("(")) {
        ++pos_;
        return Call(name);
      }
      if (Peek("[")) return std::nullopt;  // subscripts are not evaluated
      return Name(name);
    }
    return std::nullopt;
  }

  std::optional<Value> Name(const std::string& name) {
    Value out;
    out.is_number = true;
    if (name == "pi") {
      out.number = kPi;
      return out;
    }
    if (name == "True" || name == "False") {
      out.number = name == "True" ? 1 : 0;
      return out;
    }
    std::optional<Value> value = lookup_(name);
    if (!value) return std::nullopt;
    if (!value->is_number) {
      if (std::optional<double> number = ParseNumber(value->text)) {
        value->is_number = true;
        value->number = *number;
      }
    }
    return value;
  }

  std::optional<Value> Call(const std::string& name) {
    std::vector<double> args;
    if (!Eat(")")) {
      while (true) {
        std::optional<Value> arg = Comparison();
        if (!arg) return std::nullopt;
        if (!arg->is_number) {
          std::optional<double> number = ParseNumber(arg->text);
          if (!number) return std::nullopt;
          arg->number = *number;
        }
        args.push_back(arg->number);
        if (Eat(")")) break;
        if (!Eat(",")) return std::nullopt;
      }
    }
    Value out;
    out.is_number = true;
    const std::size_t n = args.size();
    if (n == 1 && name == "sqrt" && args[0] >= 0) {
      out.number = std::sqrt(args[0]);
    } else if (n == 1 && name == "sin") {
      out.number = std::sin(args[0]);
    } else if (n == 1 && name == "cos") {
      out.number = std::cos(args[0]);
    } else if (n == 1 && name == "tan") {
      out.number = std::tan(args[0]);
    } else if (n == 2 && name == "atan2") {
      out.number = std::atan2(args[0], args[1]);
    } else if (n == 1 && name == "radians") {
      out.number = args[0] * kPi / 180;
    } else if (n == 1 && name == "degrees") {
      out.number = args[0] * 180 / kPi;
    } else if (n == 1 && name == "abs") {
      out.number = std::fabs(args[0]);
    } else if (n == 1 && name == "float") {
      out.number = args[0];
    } else if (n == 1 && name == "int") {
      out.number = std::trunc(args[0]);
    } else if (n == 2 && name == "pow") {
      out.number = std::pow(args[0], args[1]);
    } else if (n >= 1 && (name == "min" || name == "max")) {
      out.number = args[0];
      for (double a : args)
        out.number = name == "min" ? std::fmin(out.number, a) : std::fmax(out.number, a);
    } else {
      return std::nullopt;
    }
    return out;
  }

  std::string_view s_;
  const NameLookup& lookup_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

std::string FormatNumber(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

}  // namespace

std::optional<Value> EvaluateExpression(std::string_view expression, const NameLookup& lookup) {
  // Inertial expressions are short; a longer one is not evaluated (each number read copies the
  // rest of the text: a hostile megabyte-long sum would take quadratic time).
  if (expression.size() > kMaxExpressionBytes) return std::nullopt;
  return Parser(expression, lookup).Run();
}

std::optional<Value> EvaluateText(std::string_view text, const NameLookup& lookup) {
  std::string out;
  std::optional<Value> single;
  int parts = 0;
  bool literal_text = false;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == '$' && i + 1 < text.size() && (text[i + 1] == '{' || text[i + 1] == '(')) {
      const char close = text[i + 1] == '{' ? '}' : ')';
      const std::size_t end = text.find(close, i + 2);
      if (end == std::string_view::npos) return std::nullopt;
      const std::string_view inner = text.substr(i + 2, end - i - 2);
      std::optional<Value> value;
      if (close == '}') {
        value = EvaluateExpression(inner, lookup);
      } else if (inner.rfind("arg ", 0) == 0) {
        std::string name(inner.substr(4));
        while (!name.empty() && name.front() == ' ') name.erase(0, 1);
        while (!name.empty() && name.back() == ' ') name.pop_back();
        value = lookup("$(arg " + name + ")");
      } else {
        value = Value{false, 0, "$(" + std::string(inner) + ")"};
      }
      if (!value) return std::nullopt;
      ++parts;
      single = value;
      out += value->is_number ? FormatNumber(value->number) : value->text;
      i = end + 1;
    } else {
      literal_text = true;
      out += text[i++];
    }
  }
  if (parts == 1 && !literal_text) return single;
  Value joined;
  joined.text = out;
  return joined;
}

std::vector<std::string> ExpressionsOf(std::string_view text) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while ((i = text.find("${", i)) != std::string_view::npos) {
    const std::size_t end = text.find('}', i + 2);
    if (end == std::string_view::npos) break;
    out.emplace_back(text.substr(i + 2, end - i - 2));
    i = end + 1;
  }
  return out;
}

std::vector<std::string> NamesOf(std::string_view expression) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < expression.size()) {
    const char c = expression[i];
    if (c == '\'' || c == '"') {
      const std::size_t end = expression.find(c, i + 1);
      if (end == std::string_view::npos) break;
      i = end + 1;
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      while (i < expression.size() && (IsIdentChar(expression[i]) ||
                                       ((expression[i] == '-' || expression[i] == '+') &&
                                        (expression[i - 1] == 'e' || expression[i - 1] == 'E')))) {
        ++i;
      }
    } else if (IsIdentStart(c)) {
      const std::size_t start = i;
      while (i < expression.size() && IsIdentChar(expression[i])) ++i;
      std::string name(expression.substr(start, i - start));
      const std::size_t dot = name.find('.');
      if (dot != std::string::npos) name = name.substr(0, dot);
      std::size_t j = i;
      while (j < expression.size() && expression[j] == ' ') ++j;
      const bool called = j < expression.size() && expression[j] == '(';
      const bool keyword = name == "pi" || name == "math" || name == "and" || name == "or" ||
                           name == "not" || name == "in" || name == "if" || name == "else" ||
                           name == "True" || name == "False";
      if (!called && !keyword && std::find(out.begin(), out.end(), name) == out.end()) {
        out.push_back(name);
      }
    } else {
      ++i;
    }
  }
  return out;
}

std::optional<double> ParseNumber(std::string_view text) {
  std::size_t a = 0, b = text.size();
  while (a < b && std::isspace(static_cast<unsigned char>(text[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(text[b - 1]))) --b;
  if (a == b) return std::nullopt;
  const std::string word(text.substr(a, b - a));
  // Python's float() also reads inf and nan; an inertial number written so is not traced.
  for (char c : word) {
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' ||
          c == 'e' || c == 'E')) {
      return std::nullopt;
    }
  }
  char* end = nullptr;
  const double value = std::strtod(word.c_str(), &end);
  if (end != word.c_str() + word.size()) return std::nullopt;
  return value;
}

std::vector<double> ParseNumbers(std::string_view text) {
  std::vector<double> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i >= text.size()) break;
    std::size_t j = i;
    while (j < text.size() && !std::isspace(static_cast<unsigned char>(text[j]))) ++j;
    std::optional<double> number = ParseNumber(text.substr(i, j - i));
    if (!number) return {};
    out.push_back(*number);
    i = j;
  }
  return out;
}

}  // namespace massprops::xacro
