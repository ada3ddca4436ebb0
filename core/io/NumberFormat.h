// Locale-independent number text for every RigidLab file format: shortest round-trip writing and strict reading.
// Writers and readers share these so that a number written by one reads back bit-exact in the other.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rl {

// Shortest text that reads back to exactly the same value (std::to_chars). Non-finite values are written as
// "nan", "inf" or "-inf"; the readers below reject them, so callers validate before writing.
void appendDouble(std::string& out, double value);
void appendFloat(std::string& out, float value);
std::string formatDouble(double value);
std::string formatFloat(float value);

// The whole text must be one finite number: decimal or exponent form, an optional leading '-' or '+'.
// No whitespace, no hex, no "nan"/"inf", nothing out of range: nullopt instead, never an exception.
std::optional<double> parseDouble(std::string_view text);
std::optional<float> parseFloat(std::string_view text);

// The whole text must be a decimal integer that fits.
std::optional<int64_t> parseInt(std::string_view text);

} // namespace rl
