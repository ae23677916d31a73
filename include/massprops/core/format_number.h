#pragma once
/// @file
/// Numbers as text, the way a person would write them: the shortest decimal that reads back as
/// exactly the same double. Used wherever massprops writes a number into a file or a message.

#include <string>

namespace massprops {

/// The shortest decimal text that reads back as exactly x (std::to_chars): 0.1 → "0.1",
/// 1e-06 → "1e-06". Negative zero is written "0". Non-finite: "nan", "inf", "-inf".
std::string FormatShortest(double x);

/// What printf's "%.*g" writes for x with `digits` significant digits (at least 1), in the C
/// locale: 0.000123456789 with 6 → "0.000123457", 1234567 with 3 → "1.23e+06", "nan", "-inf".
/// Through std::to_chars, which the standard defines as that printf conversion, at a fraction of
/// printf's cost (the text report formats every number of every finding this way).
std::string FormatPrecision(double x, int digits);

}  // namespace massprops
