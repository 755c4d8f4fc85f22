// SPDX-License-Identifier: MIT
/// @file
/// @brief Typed errors. tools/dtm/main.cpp maps them to exit codes: InputError and UsageError
/// (with OptionError) 2, Cancelled 130, any other Error 1.
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace dtm {

/// Base of every exception libdtm throws on purpose.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Bad usage: an option with a bad value, contradictory options, an unusable output path.
class UsageError : public Error {
public:
    using Error::Error;
};

/// An option has a bad value, or options contradict each other. field() names the option the way
/// the library spells it, as the member of its options struct ("z_field", "hpgl.scale",
/// "target_crs"). Library messages (of every error and warning) name options as `field`, in
/// backquotes, so that a front end can put its own spelling in their place: tools/dtm shows
/// "--z-field" (tools/dtm/option_names.cpp).
class OptionError : public UsageError {
public:
    /// @param what the whole message, naming the option as `field` where it mentions it.
    OptionError(std::string field, const std::string& what);
    [[nodiscard]] const std::string& field() const noexcept { return field_; }

private:
    std::string field_;
};

/// Malformed, unreadable or geometrically impossible input. Knows the file and, where it
/// applies, the 1-based line and column (0 = not applicable).
class InputError : public Error {
public:
    InputError(std::filesystem::path file,
               std::size_t line,
               std::size_t column,
               const std::string& what);
    /// An input problem not tied to one file (for example: all points collinear).
    explicit InputError(const std::string& what);

    [[nodiscard]] const std::filesystem::path& file() const noexcept { return file_; }
    [[nodiscard]] std::size_t line() const noexcept { return line_; }
    [[nodiscard]] std::size_t column() const noexcept { return column_; }

private:
    std::filesystem::path file_;
    std::size_t line_ = 0;
    std::size_t column_ = 0;
};

/// Thrown only by Progress when the callback asked to stop.
class Cancelled : public Error {
public:
    Cancelled() : Error("cancelled") {}
};

}  // namespace dtm
