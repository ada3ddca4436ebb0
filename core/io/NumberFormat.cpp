#include "io/NumberFormat.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace rl {

namespace {

template <class T>
void appendShortest(std::string& out, T value) {
    // 32 characters hold the longest shortest form of a double ("-2.2250738585072014e-308" is 24).
    char buffer[32];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);
    if (ec != std::errc()) {
        out += "nan"; // unreachable with this buffer size; keeps the output well formed regardless
        return;
    }
    out.append(buffer, end);
}

// Drops one leading '+' that from_chars would refuse; "+-1" stays invalid.
bool stripPlus(std::string_view& text) {
    if (!text.empty() && text.front() == '+') {
        text.remove_prefix(1);
        if (!text.empty() && text.front() == '-')
            return false;
    }
    return !text.empty();
}

template <class T>
std::optional<T> parseFinite(std::string_view text) {
    if (!stripPlus(text))
        return std::nullopt;
    // from_chars accepts "inf", "nan" and (with an 'x' after '0') nothing else surprising; reject the words
    // up front so that no non-finite value enters a scene or a bake.
    const char c = text.front() == '-' && text.size() > 1 ? text[1] : text.front();
    if (!(c >= '0' && c <= '9') && c != '.')
        return std::nullopt;
    T value{};
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value, std::chars_format::general);
    if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

} // namespace

void appendDouble(std::string& out, double value) {
    appendShortest(out, value);
}
void appendFloat(std::string& out, float value) {
    appendShortest(out, value);
}

std::string formatDouble(double value) {
    std::string out;
    appendDouble(out, value);
    return out;
}

std::string formatFloat(float value) {
    std::string out;
    appendFloat(out, value);
    return out;
}

std::optional<double> parseDouble(std::string_view text) {
    return parseFinite<double>(text);
}
std::optional<float> parseFloat(std::string_view text) {
    return parseFinite<float>(text);
}

std::optional<int64_t> parseInt(std::string_view text) {
    if (!stripPlus(text))
        return std::nullopt;
    int64_t value = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || ptr != text.data() + text.size())
        return std::nullopt;
    return value;
}

} // namespace rl
