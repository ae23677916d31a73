#include "massprops/core/format_number.h"

#include <charconv>
#include <cmath>
#include <string>

namespace massprops {

std::string FormatShortest(double x) {
  if (x == 0) return "0";
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buffer[64];
  const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof(buffer), x);
  return std::string(buffer, r.ptr);
}

}  // namespace massprops
