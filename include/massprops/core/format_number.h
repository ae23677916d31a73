#pragma once
/// @file
/// Numbers as text, the way a person would write them: the shortest decimal that reads back as
/// exactly the same double. Used wherever massprops writes a number into a file or a message.

#include <string>

namespace massprops {

/// The shortest decimal text that reads back as exactly x (std::to_chars): 0.1 → "0.1",
/// 1e-06 → "1e-06". Negative zero is written "0". Non-finite: "nan", "inf", "-inf".
std::string FormatShortest(double x);

}  // namespace massprops
