// Error reporting for bad user data (files, scenes, command-line input).
// Programmer errors are asserts; bad input is an Error that names the file, the line or object, and the problem.
#pragma once

#include <string>
#include <utility>
#include <variant>

namespace rl {

struct Error {
    std::string file;    // the file the problem is in, if any
    int line = 0;        // 1-based line, 0 when not known
    std::string object;  // body, object or JSON key the problem belongs to, if any
    std::string message; // what is wrong, in plain words
    int column = 0;      // 1-based column within the line, 0 when not known (text formats such as JSON)

    // "file:line:column: object 'name': message", leaving out the parts that are empty.
    std::string toString() const;
};

// A value or an Error. Small on purpose: C++20 has no std::expected.
template <class T>
class Result {
public:
    Result(T value) : m_data(std::move(value)) {}
    Result(Error error) : m_data(std::move(error)) {}

    bool ok() const { return m_data.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { return std::get<0>(m_data); }
    const T& value() const& { return std::get<0>(m_data); }
    T&& value() && { return std::get<0>(std::move(m_data)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() { return value(); }
    const T& operator*() const { return value(); }

    const Error& error() const { return std::get<1>(m_data); }

private:
    std::variant<T, Error> m_data;
};

// For operations that return nothing but may fail.
struct Ok {};
using Status = Result<Ok>;

} // namespace rl
