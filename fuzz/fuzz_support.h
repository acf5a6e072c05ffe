#pragma once
/// Shared by the libFuzzer targets (fuzz/README.md): the input as text, and a check that turns a
/// broken promise into a crash libFuzzer reports (with the input that caused it).

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace bunraku::fuzz {

inline std::string textOf(const std::uint8_t* data, std::size_t size) { return std::string(reinterpret_cast<const char*>(data), size); }

/// Aborts (a finding) when `condition` is false: a reader broke one of its promises.
inline void expect(bool condition, const char* what)
{
    if (condition) return;
    std::fprintf(stderr, "fuzz: broken promise: %s\n", what);
    std::abort();
}

/// An error message names the file it is about (every reader promises this).
inline bool namesSource(const std::string& message) { return message.find("fuzz-input") != std::string::npos; }

} // namespace bunraku::fuzz
