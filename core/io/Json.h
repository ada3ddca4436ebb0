// A small JSON document model with a strict reader and a pretty writer, written for .rlscene and `info --json`.
// Objects keep their key order, numbers are doubles that round-trip exactly, and every error has line and column.
#pragma once

#include "common/Result.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace rl {

struct JsonMember;

class JsonValue {
public:
    enum class Type { Null, Bool, Number, String, Array, Object };
    using Array = std::vector<JsonValue>;
    using Object = std::vector<JsonMember>; // in document order; keys are unique after parsing

    // Defined below JsonMember: clang instantiates the variant's members here, where JsonMember is incomplete.
    JsonValue();
    JsonValue(std::nullptr_t);
    JsonValue(bool value);
    JsonValue(double value);
    // Any integer (counts, indices, sizes) becomes a number; integers beyond 2^53 lose their low bits, as in JSON.
    template <class T>
    requires(std::is_integral_v<T> && !std::is_same_v<T, bool>) JsonValue(T value);
    JsonValue(std::string value);
    JsonValue(std::string_view value);
    JsonValue(const char* value);
    JsonValue(Array value);
    JsonValue(Object value);

    static JsonValue array();
    static JsonValue object();

    Type type() const { return static_cast<Type>(m_data.index()); }
    bool isNull() const { return type() == Type::Null; }
    bool isBool() const { return type() == Type::Bool; }
    bool isNumber() const { return type() == Type::Number; }
    bool isString() const { return type() == Type::String; }
    bool isArray() const { return type() == Type::Array; }
    bool isObject() const { return type() == Type::Object; }

    // Accessors assert the type; check it first (readers turn a wrong type into an Error naming the key).
    bool asBool() const { return std::get<bool>(m_data); }
    double asNumber() const { return std::get<double>(m_data); }
    const std::string& asString() const { return std::get<std::string>(m_data); }
    const Array& asArray() const { return std::get<Array>(m_data); }
    Array& asArray() { return std::get<Array>(m_data); }
    const Object& asObject() const { return std::get<Object>(m_data); }
    Object& asObject() { return std::get<Object>(m_data); }

    // Object member lookup; nullptr when this is not an object or has no such key.
    const JsonValue* find(std::string_view key) const;
    // Object: replaces the value of an existing key or appends a new one, so insertion order is kept.
    JsonValue& set(std::string key, JsonValue value);
    // Array: appends.
    JsonValue& push(JsonValue value);

    // Where the value started in the parsed text (1-based); 0 for values built in code.
    int line() const { return m_line; }
    int column() const { return m_column; }
    void setPosition(int line, int column) {
        m_line = line;
        m_column = column;
    }

    // Structural equality; positions are ignored.
    bool operator==(const JsonValue& other) const;

private:
    std::variant<std::nullptr_t, bool, double, std::string, Array, Object> m_data;
    int m_line = 0;
    int m_column = 0;
};

struct JsonMember {
    std::string key;
    JsonValue value;
    int line = 0; // where the key stood in the parsed text (1-based), so that "unknown key" points at the key
    int column = 0;
    // Positions are ignored, as for JsonValue.
    bool operator==(const JsonMember& other) const { return key == other.key && value == other.value; }
};

inline JsonValue::JsonValue() = default;
inline JsonValue::JsonValue(std::nullptr_t) {}
inline JsonValue::JsonValue(bool value) : m_data(value) {}
inline JsonValue::JsonValue(double value) : m_data(value) {}
template <class T>
requires(std::is_integral_v<T> && !std::is_same_v<T, bool>) inline JsonValue::JsonValue(T value)
    : m_data(static_cast<double>(value)) {}
inline JsonValue::JsonValue(std::string value) : m_data(std::move(value)) {}
inline JsonValue::JsonValue(std::string_view value) : m_data(std::string(value)) {}
inline JsonValue::JsonValue(const char* value) : m_data(std::string(value)) {}
inline JsonValue::JsonValue(Array value) : m_data(std::move(value)) {}
inline JsonValue::JsonValue(Object value) : m_data(std::move(value)) {}
inline JsonValue JsonValue::array() {
    return JsonValue(Array{});
}
inline JsonValue JsonValue::object() {
    return JsonValue(Object{});
}
inline bool JsonValue::operator==(const JsonValue& other) const {
    return m_data == other.m_data;
}

std::string_view jsonTypeName(JsonValue::Type type); // "null", "boolean", "number", "string", "array", "object"

struct JsonReadOptions {
    // Hostile input must not exhaust the stack or memory: real scenes nest 4 levels and weigh a few megabytes.
    int maxDepth = 128;
    size_t maxBytes = size_t(512) << 20;
};

// Strict RFC 8259: one value, no comments, no trailing commas, valid UTF-8, no lone surrogates, no duplicate keys,
// numbers that fit a double. A UTF-8 byte order mark is skipped. Errors carry fileName, line and column:
// "scene.rlscene:12:5: expected ',' or '}'".
Result<JsonValue> parseJson(std::string_view text, const std::string& fileName = {},
                            const JsonReadOptions& options = {});

// Pretty text with `indent` spaces per level (0 gives one compact line). Arrays of scalars stay on one line so that
// vectors and quaternions read naturally. Numbers are shortest round-trip; non-finite numbers become null
// because JSON has no spelling for them (writers validate first). Ends with a newline when indent > 0.
std::string writeJson(const JsonValue& value, int indent = 2);

} // namespace rl
