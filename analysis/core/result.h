#pragma once
/// Result<T>: the value of an operation on expected-to-be-bad input, or an Error saying what
/// was wrong and where. Broken programming preconditions assert instead; "no answer" from an
/// iterative method is std::optional.

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace bunraku::analysis {

enum class ErrorCode {
    InvalidArgument, ///< a parameter out of its documented range
    Parse,           ///< malformed input text; the message names file, line and expectation
    Io,              ///< a file could not be read or written
    NotFound,        ///< a named channel, joint, take or file does not exist
    Numerical,       ///< singular or degenerate data (NaN, equal moments, zero variance...)
    Cancelled,       ///< the caller's stop token was triggered
    Unsupported,     ///< a valid input this version does not handle
};

struct Error {
    ErrorCode code = ErrorCode::InvalidArgument;
    std::string message;
};

inline Error makeError(ErrorCode code, std::string message) { return Error{code, std::move(message)}; }

/// "file:line: what was expected" for parse errors; line is 1-based, 0 omits it.
inline Error parseError(const std::string& file, long line, const std::string& what)
{
    // Appended piecewise: GCC 12 reports a false -Wrestrict on chained operator+ here at -O3.
    std::string message = file;
    if (line > 0) {
        message.push_back(':');
        message.append(std::to_string(line));
    }
    message.append(": ");
    message.append(what);
    return Error{ErrorCode::Parse, std::move(message)};
}

template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : m_state(std::in_place_index<0>, std::move(value)) {}
    Result(Error error) : m_state(std::in_place_index<1>, std::move(error)) {}

    bool ok() const { return m_state.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { assert(ok()); return std::get<0>(m_state); }
    const T& value() const& { assert(ok()); return std::get<0>(m_state); }
    T&& value() && { assert(ok()); return std::get<0>(std::move(m_state)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const { assert(!ok()); return std::get<1>(m_state); }

private:
    std::variant<T, Error> m_state;
};

/// Success or an Error, for operations with no value to return.
using Status = Result<std::monostate>;
inline Status okStatus() { return std::monostate{}; }

} // namespace bunraku::analysis
