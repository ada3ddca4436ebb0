#include "io/Json.h"

#include "io/NumberFormat.h"

#include <cmath>
#include <cstdint>
#include <unordered_set>

namespace rl {

const JsonValue* JsonValue::find(std::string_view key) const {
    if (!isObject())
        return nullptr;
    for (const JsonMember& m : asObject())
        if (m.key == key)
            return &m.value;
    return nullptr;
}

JsonValue& JsonValue::set(std::string key, JsonValue value) {
    Object& members = asObject();
    for (JsonMember& m : members)
        if (m.key == key) {
            m.value = std::move(value);
            return m.value;
        }
    members.push_back(JsonMember{std::move(key), std::move(value)});
    return members.back().value;
}

JsonValue& JsonValue::push(JsonValue value) {
    Array& items = asArray();
    items.push_back(std::move(value));
    return items.back();
}

std::string_view jsonTypeName(JsonValue::Type type) {
    switch (type) {
    case JsonValue::Type::Null:
        return "null";
    case JsonValue::Type::Bool:
        return "boolean";
    case JsonValue::Type::Number:
        return "number";
    case JsonValue::Type::String:
        return "string";
    case JsonValue::Type::Array:
        return "array";
    case JsonValue::Type::Object:
        return "object";
    }
    return "value";
}

namespace {

// Objects with more members than this check duplicates with a hash set instead of a linear scan, so that a hostile
// object with a million keys costs O(n), not O(n^2).
constexpr size_t kLinearDuplicateScan = 16;

class Parser {
public:
    Parser(std::string_view text, const std::string& fileName, const JsonReadOptions& options)
        : m_text(text), m_fileName(fileName), m_options(options) {}

    Result<JsonValue> run() {
        if (m_text.size() > m_options.maxBytes)
            return Error{m_fileName,
                         0,
                         {},
                         "JSON text is larger than the limit of " + std::to_string(m_options.maxBytes) + " bytes"};
        if (m_text.substr(0, 3) == "\xEF\xBB\xBF")
            m_pos = m_lineStart = 3;
        JsonValue root;
        skipWhitespace();
        if (!parseValue(root, 0))
            return m_error;
        skipWhitespace();
        if (m_pos != m_text.size()) {
            fail("unexpected text after the JSON value");
            return m_error;
        }
        return root;
    }

private:
    bool fail(std::string message) { return failAt(m_pos, std::move(message)); }

    bool failAt(size_t pos, std::string message) {
        m_error = Error{m_fileName, m_line, {}, std::move(message), static_cast<int>(pos - m_lineStart) + 1};
        return false;
    }

    bool atEnd() const { return m_pos >= m_text.size(); }
    char peek() const { return m_text[m_pos]; }

    void skipWhitespace() {
        while (!atEnd()) {
            const char c = peek();
            if (c == '\n') {
                ++m_line;
                m_lineStart = m_pos + 1;
            } else if (c != ' ' && c != '\t' && c != '\r') {
                break;
            }
            ++m_pos;
        }
    }

    bool parseValue(JsonValue& out, int depth) {
        if (atEnd())
            return fail("unexpected end of file, expected a value");
        const int line = m_line;
        const int column = static_cast<int>(m_pos - m_lineStart) + 1;
        bool ok = false;
        switch (peek()) {
        case '{':
            ok = parseObject(out, depth + 1);
            break;
        case '[':
            ok = parseArray(out, depth + 1);
            break;
        case '"': {
            std::string s;
            ok = parseString(s);
            out = JsonValue(std::move(s));
            break;
        }
        case 't':
            ok = parseWord("true", JsonValue(true), out);
            break;
        case 'f':
            ok = parseWord("false", JsonValue(false), out);
            break;
        case 'n':
            ok = parseWord("null", JsonValue(), out);
            break;
        default:
            if (peek() == '-' || (peek() >= '0' && peek() <= '9'))
                ok = parseNumber(out);
            else
                ok = fail("expected a value");
        }
        if (ok)
            out.setPosition(line, column);
        return ok;
    }

    bool parseWord(std::string_view word, JsonValue value, JsonValue& out) {
        if (m_text.substr(m_pos, word.size()) != word)
            return fail("expected a value");
        m_pos += word.size();
        out = std::move(value);
        return true;
    }

    bool digitAt(size_t pos) const { return pos < m_text.size() && m_text[pos] >= '0' && m_text[pos] <= '9'; }

    bool parseNumber(JsonValue& out) {
        // Validate the JSON grammar first: from_chars alone would accept "01", "1." or ".5".
        const size_t start = m_pos;
        size_t p = m_pos;
        if (m_text[p] == '-')
            ++p;
        if (!digitAt(p))
            return failAt(p, "invalid number: expected a digit");
        if (m_text[p] == '0') {
            ++p;
            if (digitAt(p))
                return failAt(p, "invalid number: leading zero");
        } else {
            while (digitAt(p))
                ++p;
        }
        if (p < m_text.size() && m_text[p] == '.') {
            ++p;
            if (!digitAt(p))
                return failAt(p, "invalid number: expected a digit after '.'");
            while (digitAt(p))
                ++p;
        }
        if (p < m_text.size() && (m_text[p] == 'e' || m_text[p] == 'E')) {
            ++p;
            if (p < m_text.size() && (m_text[p] == '+' || m_text[p] == '-'))
                ++p;
            if (!digitAt(p))
                return failAt(p, "invalid number: expected a digit in the exponent");
            while (digitAt(p))
                ++p;
        }
        const std::optional<double> value = parseDouble(m_text.substr(start, p - start));
        if (!value)
            return failAt(start,
                          "number out of range: " + std::string(m_text.substr(start, std::min<size_t>(p - start, 40))));
        m_pos = p;
        out = JsonValue(*value);
        return true;
    }

    static void appendUtf8(std::string& out, uint32_t cp) {
        if (cp < 0x80) {
            out += static_cast<char>(cp);
        } else if (cp < 0x800) {
            out += static_cast<char>(0xC0 | (cp >> 6));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += static_cast<char>(0xE0 | (cp >> 12));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (cp >> 18));
            out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        }
    }

    bool parseHex4(size_t at, uint32_t& out) {
        if (at + 4 > m_text.size())
            return failAt(at, "invalid \\u escape: expected four hex digits");
        out = 0;
        for (size_t i = at; i < at + 4; ++i) {
            const char c = m_text[i];
            uint32_t d;
            if (c >= '0' && c <= '9')
                d = static_cast<uint32_t>(c - '0');
            else if (c >= 'a' && c <= 'f')
                d = static_cast<uint32_t>(c - 'a' + 10);
            else if (c >= 'A' && c <= 'F')
                d = static_cast<uint32_t>(c - 'A' + 10);
            else
                return failAt(i, "invalid \\u escape: expected four hex digits");
            out = out * 16 + d;
        }
        return true;
    }

    // Length of the valid UTF-8 sequence at pos (overlongs, surrogates and values above U+10FFFF are invalid), or 0.
    size_t utf8Length(size_t pos) const {
        const auto byte = [&](size_t i) { return i < m_text.size() ? static_cast<unsigned char>(m_text[i]) : 0u; };
        const unsigned c = byte(pos);
        const auto cont = [&](size_t i) { return (byte(i) & 0xC0) == 0x80; };
        if (c >= 0xC2 && c <= 0xDF)
            return cont(pos + 1) ? 2 : 0;
        if (c >= 0xE0 && c <= 0xEF) {
            const unsigned c1 = byte(pos + 1);
            if ((c == 0xE0 && c1 < 0xA0) || (c == 0xED && c1 >= 0xA0))
                return 0;
            return cont(pos + 1) && cont(pos + 2) ? 3 : 0;
        }
        if (c >= 0xF0 && c <= 0xF4) {
            const unsigned c1 = byte(pos + 1);
            if ((c == 0xF0 && c1 < 0x90) || (c == 0xF4 && c1 >= 0x90))
                return 0;
            return cont(pos + 1) && cont(pos + 2) && cont(pos + 3) ? 4 : 0;
        }
        return 0;
    }

    bool parseString(std::string& out) {
        const size_t open = m_pos;
        ++m_pos; // opening quote
        while (true) {
            if (atEnd())
                return failAt(open, "unterminated string");
            const unsigned char c = static_cast<unsigned char>(peek());
            if (c == '"') {
                ++m_pos;
                return true;
            }
            if (c < 0x20)
                return fail(c == '\n' ? "unterminated string (raw line break)" : "control character in string");
            if (c >= 0x80) {
                const size_t n = utf8Length(m_pos);
                if (n == 0)
                    return fail("invalid UTF-8 in string");
                out.append(m_text.substr(m_pos, n));
                m_pos += n;
                continue;
            }
            if (c != '\\') {
                out += static_cast<char>(c);
                ++m_pos;
                continue;
            }
            if (m_pos + 1 >= m_text.size())
                return failAt(open, "unterminated string");
            const char e = m_text[m_pos + 1];
            switch (e) {
            case '"':
            case '\\':
            case '/':
                out += e;
                break;
            case 'b':
                out += '\b';
                break;
            case 'f':
                out += '\f';
                break;
            case 'n':
                out += '\n';
                break;
            case 'r':
                out += '\r';
                break;
            case 't':
                out += '\t';
                break;
            case 'u': {
                uint32_t cp = 0;
                if (!parseHex4(m_pos + 2, cp))
                    return false;
                if (cp >= 0xDC00 && cp <= 0xDFFF)
                    return fail("lone low surrogate in \\u escape");
                if (cp >= 0xD800 && cp <= 0xDBFF) {
                    // A high surrogate must be followed by an escaped low surrogate; together they are one code point.
                    const size_t next = m_pos + 6;
                    uint32_t low = 0;
                    if (m_text.substr(next, 2) != "\\u" || !parseHex4(next + 2, low) || low < 0xDC00 || low > 0xDFFF)
                        return fail("high surrogate in \\u escape without a low surrogate after it");
                    cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
                    m_pos += 6;
                }
                appendUtf8(out, cp);
                m_pos += 4;
                break;
            }
            default:
                return fail(std::string("invalid escape '\\") + (e >= 0x20 && e < 0x7F ? std::string(1, e) : "?") +
                            "'");
            }
            m_pos += 2;
        }
    }

    bool parseArray(JsonValue& out, int depth) {
        if (depth > m_options.maxDepth)
            return fail("nesting deeper than " + std::to_string(m_options.maxDepth) + " levels");
        ++m_pos; // '['
        JsonValue::Array items;
        skipWhitespace();
        if (!atEnd() && peek() == ']') {
            ++m_pos;
            out = JsonValue(std::move(items));
            return true;
        }
        while (true) {
            skipWhitespace();
            items.emplace_back();
            if (!parseValue(items.back(), depth))
                return false;
            skipWhitespace();
            if (atEnd())
                return fail("unexpected end of file, expected ',' or ']'");
            if (peek() == ',') {
                ++m_pos;
                continue;
            }
            if (peek() == ']') {
                ++m_pos;
                out = JsonValue(std::move(items));
                return true;
            }
            return fail("expected ',' or ']'");
        }
    }

    bool parseObject(JsonValue& out, int depth) {
        if (depth > m_options.maxDepth)
            return fail("nesting deeper than " + std::to_string(m_options.maxDepth) + " levels");
        ++m_pos; // '{'
        JsonValue::Object members;
        std::unordered_set<std::string> seen; // filled only for large objects
        skipWhitespace();
        if (!atEnd() && peek() == '}') {
            ++m_pos;
            out = JsonValue(std::move(members));
            return true;
        }
        while (true) {
            skipWhitespace();
            if (atEnd())
                return fail("unexpected end of file, expected a key");
            if (peek() != '"')
                return fail("expected a string key");
            const size_t keyPos = m_pos;
            const int keyLine = m_line;
            const int keyColumn = static_cast<int>(keyPos - m_lineStart) + 1;
            std::string key;
            if (!parseString(key))
                return false;
            bool duplicate = false;
            if (members.size() < kLinearDuplicateScan) {
                for (const JsonMember& m : members)
                    duplicate = duplicate || m.key == key;
            } else {
                if (seen.empty())
                    for (const JsonMember& m : members)
                        seen.insert(m.key);
                duplicate = !seen.insert(key).second;
            }
            if (duplicate)
                return failAt(keyPos, "duplicate key '" + key + "'");
            skipWhitespace();
            if (atEnd() || peek() != ':')
                return fail("expected ':' after key '" + key + "'");
            ++m_pos;
            skipWhitespace();
            members.push_back(JsonMember{std::move(key), JsonValue(), keyLine, keyColumn});
            if (!parseValue(members.back().value, depth))
                return false;
            skipWhitespace();
            if (atEnd())
                return fail("unexpected end of file, expected ',' or '}'");
            if (peek() == ',') {
                ++m_pos;
                continue;
            }
            if (peek() == '}') {
                ++m_pos;
                out = JsonValue(std::move(members));
                return true;
            }
            return fail("expected ',' or '}'");
        }
    }

    std::string_view m_text;
    const std::string& m_fileName;
    const JsonReadOptions& m_options;
    size_t m_pos = 0;
    size_t m_lineStart = 0;
    int m_line = 1;
    Error m_error;
};

void writeString(std::string& out, const std::string& s) {
    static constexpr char kHex[] = "0123456789abcdef";
    out += '"';
    for (const char ch : s) {
        const unsigned char c = static_cast<unsigned char>(ch);
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        case '\b':
            out += "\\b";
            break;
        case '\f':
            out += "\\f";
            break;
        default:
            if (c < 0x20) {
                out += "\\u00";
                out += kHex[c >> 4];
                out += kHex[c & 0xF];
            } else {
                out += ch; // UTF-8 passes through unchanged
            }
        }
    }
    out += '"';
}

bool isScalar(const JsonValue& v) {
    return !v.isArray() && !v.isObject();
}

// Recursion follows the nesting of the value; parsed values are at most maxDepth deep.
void writeValue(std::string& out, const JsonValue& v, int indent, int level) {
    const auto newline = [&](int lvl) {
        if (indent > 0) {
            out += '\n';
            out.append(static_cast<size_t>(indent * lvl), ' ');
        }
    };
    switch (v.type()) {
    case JsonValue::Type::Null:
        out += "null";
        return;
    case JsonValue::Type::Bool:
        out += v.asBool() ? "true" : "false";
        return;
    case JsonValue::Type::Number:
        if (std::isfinite(v.asNumber()))
            appendDouble(out, v.asNumber());
        else
            out += "null";
        return;
    case JsonValue::Type::String:
        writeString(out, v.asString());
        return;
    case JsonValue::Type::Array: {
        const JsonValue::Array& items = v.asArray();
        if (items.empty()) {
            out += "[]";
            return;
        }
        bool inlineItems = indent == 0;
        if (!inlineItems) {
            inlineItems = true;
            for (const JsonValue& item : items)
                inlineItems = inlineItems && isScalar(item);
        }
        out += '[';
        for (size_t i = 0; i < items.size(); ++i) {
            if (i > 0)
                out += inlineItems && indent > 0 ? ", " : ",";
            if (!inlineItems)
                newline(level + 1);
            writeValue(out, items[i], indent, level + 1);
        }
        if (!inlineItems)
            newline(level);
        out += ']';
        return;
    }
    case JsonValue::Type::Object: {
        const JsonValue::Object& members = v.asObject();
        if (members.empty()) {
            out += "{}";
            return;
        }
        out += '{';
        for (size_t i = 0; i < members.size(); ++i) {
            if (i > 0)
                out += ',';
            newline(level + 1);
            writeString(out, members[i].key);
            out += indent > 0 ? ": " : ":";
            writeValue(out, members[i].value, indent, level + 1);
        }
        newline(level);
        out += '}';
        return;
    }
    }
}

} // namespace

Result<JsonValue> parseJson(std::string_view text, const std::string& fileName, const JsonReadOptions& options) {
    return Parser(text, fileName, options).run();
}

std::string writeJson(const JsonValue& value, int indent) {
    std::string out;
    writeValue(out, value, indent, 0);
    if (indent > 0)
        out += '\n';
    return out;
}

} // namespace rl
