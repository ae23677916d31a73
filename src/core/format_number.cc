#include "massprops/core/format_number.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

namespace massprops {

std::string FormatShortest(double x) {
  if (x == 0) return "0";
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buffer[64];
  const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof(buffer), x);
  return std::string(buffer, r.ptr);
}

std::string FormatPrecision(double x, int digits) {
  // A sign, the digits, a point and "e-308" fit in 64 bytes up to 56 digits (massprops asks for at
  // most 17); a double's exact expansion (up to 767 digits) in the bigger buffer.
  char buffer[64];
  const int precision = std::max(1, digits);
  const std::to_chars_result r =
      std::to_chars(buffer, buffer + sizeof(buffer), x, std::chars_format::general, precision);
  if (r.ec == std::errc()) return std::string(buffer, r.ptr);
  std::string text(800, '\0');
  const std::to_chars_result wide = std::to_chars(text.data(), text.data() + text.size(), x,
                                                  std::chars_format::general, precision);
  text.resize(static_cast<std::size_t>(wide.ptr - text.data()));
  return text;
}

}  // namespace massprops
