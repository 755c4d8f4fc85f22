// SPDX-License-Identifier: MIT
// The expat wrapper of xml_sax.hpp. Expat is C: an exception must not unwind through it, so the
// callbacks catch, stop the parser and parse() rethrows.
#include "io/formats/xml/xml_sax.hpp"

#include <expat.h>

#include <exception>
#include <fstream>
#include <vector>

#include "dtm/core/error.hpp"

namespace dtm::io::xml {

std::string_view attribute(std::span<const Attribute> attributes, std::string_view name) noexcept {
    for (const Attribute& a : attributes) {
        if (a.name == name) return a.value;
    }
    return {};
}

namespace {

constexpr char namespace_separator = '\x01';

std::string_view local_name(const XML_Char* name) noexcept {
    std::string_view n(name);
    const std::size_t at = n.rfind(namespace_separator);
    return at == std::string_view::npos ? n : n.substr(at + 1);
}

struct Context {
    Parser* parser;
    Handler* handler;
    XML_Parser expat;
    std::string text;
    std::vector<Attribute> attributes;
    std::exception_ptr error;
};

void stop(Context& c) {
    c.error = std::current_exception();
    XML_StopParser(c.expat, XML_FALSE);
}

void on_start(void* data, const XML_Char* name, const XML_Char** atts) {
    auto& c = *static_cast<Context*>(data);
    if (c.error) return;
    try {
        c.attributes.clear();
        for (const XML_Char** a = atts; *a != nullptr; a += 2) {
            c.attributes.push_back({local_name(a[0]), std::string_view(a[1])});
        }
        c.handler->start(*c.parser, local_name(name), c.attributes);
        c.text.clear();
    } catch (...) {
        stop(c);
    }
}

void on_end(void* data, const XML_Char* name) {
    auto& c = *static_cast<Context*>(data);
    if (c.error) return;
    try {
        c.handler->end(*c.parser, local_name(name), c.text);
        c.text.clear();
    } catch (...) {
        stop(c);
    }
}

void on_text(void* data, const XML_Char* s, int len) {
    auto& c = *static_cast<Context*>(data);
    c.text.append(s, static_cast<std::size_t>(len));
}

}  // namespace

std::size_t Parser::line() const noexcept {
    return parser_ == nullptr ? 0
                              : static_cast<std::size_t>(
                                    XML_GetCurrentLineNumber(static_cast<XML_Parser>(parser_)));
}

std::size_t Parser::column() const noexcept {
    return parser_ == nullptr ? 0
                              : static_cast<std::size_t>(
                                    XML_GetCurrentColumnNumber(static_cast<XML_Parser>(parser_))) +
                                    1;
}

void Parser::fail(const std::string& what) const {
    throw InputError(path_, line(), column(), what);
}

void Parser::parse(Handler& handler, const Progress& progress) {
    std::ifstream in(path_, std::ios::binary);
    if (!in) throw InputError(path_, 0, 0, "cannot open the file");
    in.seekg(0, std::ios::end);
    const auto size = static_cast<double>(in.tellg());
    in.seekg(0);
    XML_Parser expat = XML_ParserCreateNS(nullptr, namespace_separator);
    if (expat == nullptr) throw Error("cannot create an XML parser");
    struct Free {
        XML_Parser p;
        Parser& owner;
        ~Free() {
            XML_ParserFree(p);
            owner.parser_ = nullptr;
        }
    } free_parser{expat, *this};
    parser_ = expat;
    Context c{this, &handler, expat, {}, {}, {}};
    XML_SetUserData(expat, &c);
    XML_SetElementHandler(expat, &on_start, &on_end);
    XML_SetCharacterDataHandler(expat, &on_text);
    constexpr std::size_t block = std::size_t{1} << 20;
    double done = 0;
    for (;;) {
        void* buffer = XML_GetBuffer(expat, static_cast<int>(block));
        if (buffer == nullptr) throw Error("out of memory reading " + path_.string());
        in.read(static_cast<char*>(buffer), static_cast<std::streamsize>(block));
        const auto got = static_cast<int>(in.gcount());
        const bool last = got == 0 || in.eof();
        if (XML_ParseBuffer(expat, got, last ? XML_TRUE : XML_FALSE) == XML_STATUS_ERROR) {
            if (c.error) std::rethrow_exception(c.error);
            throw InputError(
                path_, line(), column(),
                std::string("malformed XML: ") + XML_ErrorString(XML_GetErrorCode(expat)));
        }
        if (last) break;
        done += got;
        if (size > 0) progress.report(done / size);
    }
}

std::string_view root_element(std::string_view bytes) noexcept {
    std::size_t at = 0;
    if (bytes.starts_with("\xEF\xBB\xBF")) at = 3;
    while (true) {
        at = bytes.find('<', at);
        if (at == std::string_view::npos || at + 1 >= bytes.size()) return {};
        const char next = bytes[at + 1];
        if (next == '?') {
            at = bytes.find("?>", at);
        } else if (bytes.substr(at, 4) == "<!--") {
            at = bytes.find("-->", at);
        } else if (next == '!') {
            at = bytes.find('>', at);
        } else {
            std::size_t end = at + 1;
            while (end < bytes.size() && bytes[end] != '>' && bytes[end] != '/' &&
                   bytes[end] != ' ' && bytes[end] != '\t' && bytes[end] != '\r' &&
                   bytes[end] != '\n') {
                ++end;
            }
            std::string_view name = bytes.substr(at + 1, end - at - 1);
            const std::size_t colon = name.find(':');
            return colon == std::string_view::npos ? name : name.substr(colon + 1);
        }
        if (at == std::string_view::npos) return {};
    }
}

}  // namespace dtm::io::xml
