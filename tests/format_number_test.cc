// FormatShortest and FormatPrecision (massprops/core/format_number.h): numbers as text.
#include "massprops/core/format_number.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>

namespace massprops {
namespace {

TEST(FormatShortestTest, WritesTheShortestTextThatReadsBack) {
  // Shortest round-trip forms (std::to_chars, C++17 [charconv.to.chars]).
  EXPECT_EQ(FormatShortest(0.1), "0.1");
  EXPECT_EQ(FormatShortest(2), "2");
  EXPECT_EQ(FormatShortest(1e-6), "1e-06");
  EXPECT_EQ(FormatShortest(-0.0045), "-0.0045");
  EXPECT_EQ(FormatShortest(-0.0), "0");
  EXPECT_EQ(FormatShortest(1.0 / 3), "0.3333333333333333");
}

TEST(FormatShortestTest, RandomDoublesRoundTrip) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-30, 30);
  for (int i = 0; i < 10000; ++i) {
    const double x = std::ldexp(mantissa(rng), exponent(rng));
    EXPECT_EQ(std::strtod(FormatShortest(x).c_str(), nullptr), x) << FormatShortest(x);
  }
}

// The C library's printf, the definition FormatPrecision follows (C11 7.21.6.1, "%g").
std::string Printf(double x, int digits) {
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return buffer;
}

TEST(FormatPrecisionTest, WritesWhatPrintfsPercentGWrites) {
  // By hand, from the rules of %g: exponent form when the exponent is below -4 or not below the
  // precision; trailing zeros removed.
  EXPECT_EQ(FormatPrecision(0.000123456789, 6), "0.000123457");
  EXPECT_EQ(FormatPrecision(0.0000123456789, 6), "1.23457e-05");
  EXPECT_EQ(FormatPrecision(1234567, 3), "1.23e+06");
  EXPECT_EQ(FormatPrecision(123456, 6), "123456");
  EXPECT_EQ(FormatPrecision(1234567, 6), "1.23457e+06");
  EXPECT_EQ(FormatPrecision(2.5, 6), "2.5");
  EXPECT_EQ(FormatPrecision(-0.0, 3), "-0");
  EXPECT_EQ(FormatPrecision(9.9996, 4), "10");
  EXPECT_EQ(FormatPrecision(1e300, 3), "1e+300");
  EXPECT_EQ(FormatPrecision(0.5, 0), "0.5");  // precision 0 counts as 1
  EXPECT_EQ(FormatPrecision(std::numeric_limits<double>::infinity(), 3), "inf");
  EXPECT_EQ(FormatPrecision(-std::numeric_limits<double>::infinity(), 3), "-inf");
  EXPECT_EQ(FormatPrecision(std::numeric_limits<double>::quiet_NaN(), 3), "nan");
  // A double's exact decimal expansion (more digits than any short buffer holds).
  EXPECT_EQ(FormatPrecision(0.1, 60), Printf(0.1, 60));
  EXPECT_EQ(FormatPrecision(std::numeric_limits<double>::denorm_min(), 800),
            Printf(std::numeric_limits<double>::denorm_min(), 800));
}

TEST(FormatPrecisionTest, RandomDoublesAtEveryPrecisionAreWhatPrintfWrites) {
  // Random doubles over the whole exponent range, halfway cases (x.5 at the last digit) and
  // subnormals, at the precisions massprops writes (3, 4, 6, 17) and others.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-1074, 1023);
  std::uniform_int_distribution<int> digits(1, 20);
  for (int i = 0; i < 20000; ++i) {
    const double x = std::ldexp(mantissa(rng), exponent(rng));
    const int d = digits(rng);
    ASSERT_EQ(FormatPrecision(x, d), Printf(x, d)) << x << " " << d;
  }
  for (int i = 0; i < 2000; ++i) {
    const double half = (i + 0.5) / 1000.0;  // 0.0005, 0.0015, ...: ties at the third digit
    for (int d : {1, 2, 3, 4, 6, 17}) ASSERT_EQ(FormatPrecision(half, d), Printf(half, d));
  }
}

}  // namespace
}  // namespace massprops
