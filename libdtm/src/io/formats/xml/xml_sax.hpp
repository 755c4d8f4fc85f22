// SPDX-License-Identifier: MIT
// A streaming XML reader on expat (ADR 0006) for the XML formats (LandXML, JVF DTM): elements by
// local name (namespaces are ignored, so LandXML 1.1, 1.2 and profiles such as Inframodel read
// alike), the character data of each element, encodings expat knows (UTF-8, UTF-16, ISO-8859-1,
// US-ASCII) converted to UTF-8. Errors carry the file, line and column.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "dtm/core/progress.hpp"

namespace dtm::io::xml {

struct Attribute {
    std::string_view name;  ///< local name (prefix and namespace removed)
    std::string_view value;
};

/// The attribute named @p name, or an empty view.
[[nodiscard]] std::string_view attribute(std::span<const Attribute> attributes,
                                         std::string_view name) noexcept;

class Parser;

/// What a format reader does with the elements. Exceptions thrown here stop the parse and come
/// out of Parser::parse().
class Handler {
public:
    virtual ~Handler() = default;
    virtual void start(Parser& parser,
                       std::string_view name,
                       std::span<const Attribute> attributes) = 0;
    /// @p text: the character data since the last start or end tag (an element's text when it
    /// has no children).
    virtual void end(Parser& parser, std::string_view name, std::string_view text) = 0;
};

class Parser {
public:
    explicit Parser(std::filesystem::path path) : path_(std::move(path)) {}
    /// Reads the whole file in blocks. @throws InputError (file, line, column) for malformed
    /// XML or an unreadable file; whatever the handler throws.
    void parse(Handler& handler, const Progress& progress);
    /// The position of the current event (1-based line and column).
    [[nodiscard]] std::size_t line() const noexcept;
    [[nodiscard]] std::size_t column() const noexcept;
    [[nodiscard]] const std::filesystem::path& path() const noexcept { return path_; }
    /// An InputError at the current position.
    [[noreturn]] void fail(const std::string& what) const;

private:
    std::filesystem::path path_;
    void* parser_ = nullptr;  // XML_Parser while parse() runs
};

/// The local name of the root element of a file that starts with @p bytes (skipping the XML
/// declaration, comments, processing instructions and a DOCTYPE), or empty.
[[nodiscard]] std::string_view root_element(std::string_view bytes) noexcept;

}  // namespace dtm::io::xml
