// SPDX-License-Identifier: MIT
/// @file
/// @brief HP-GL tokenizer: unwraps PCL/PJL and RS-232 device-control escapes and cuts the byte
/// stream into two-letter instructions with numeric parameters, label text (LB ... terminator)
/// or decoded PE (polyline encoded) data. Works on missing separators ("PUSP1PA10,20PD").
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "io/formats/hpgl/hpgl_pe.hpp"

namespace dtm::io::hpgl {

/// Collects problems found in the bytes. Strict: the first problem throws
/// InputError(file, "byte N: ..."); otherwise problems become (capped) warnings.
class Diagnostics {
public:
    Diagnostics(std::filesystem::path file, bool strict)
        : file_(std::move(file)), strict_(strict) {}
    /// A corrupt or unreadable part of the input at byte @p offset (0-based).
    void problem(std::size_t offset, const std::string& what);
    /// Something worth telling the user that is not corruption.
    void warn(const std::string& what);
    [[nodiscard]] std::size_t problems() const noexcept { return problems_; }
    [[nodiscard]] const std::vector<std::string>& warnings() const noexcept { return warnings_; }
    [[nodiscard]] std::vector<std::string> take_warnings();

private:
    std::filesystem::path file_;
    bool strict_;
    std::size_t problems_ = 0;
    std::vector<std::string> warnings_;
};

/// One instruction. Views point into the input bytes; vectors are reused between calls.
struct Command {
    char name[2] = {0, 0};       ///< upper-case mnemonic
    std::size_t offset = 0;      ///< byte offset of the mnemonic
    std::vector<double> params;  ///< numeric parameters in order (quoted strings skipped)
    std::string_view text;       ///< LB/BL/WD label text (without terminator); SM symbol
    std::vector<PeItem> pe;      ///< decoded PE items
    [[nodiscard]] bool is(const char (&mnemonic)[3]) const noexcept {
        return name[0] == mnemonic[0] && name[1] == mnemonic[1];
    }
};

class Lexer {
public:
    Lexer(std::string_view bytes, Diagnostics& diagnostics) : bytes_(bytes), diag_(diagnostics) {}
    /// Reads the next instruction into @p command; false at the end of the input.
    bool next(Command& command);
    [[nodiscard]] std::size_t position() const noexcept { return pos_; }
    /// True once any HP-GL instruction was found (false for a PCL-only file).
    [[nodiscard]] bool saw_hpgl() const noexcept { return saw_hpgl_; }

    /// Reports text left at the end (stray runs skipped).
    void finish();

private:
    void skip_stray();
    void skip_escape();
    void skip_pcl_parameterized();
    void skip_pjl_lines();
    void read_numbers(Command& command);
    void read_label(Command& command);
    void read_terminator_definition(Command& command);
    void read_symbol_mode(Command& command);

    std::string_view bytes_;
    Diagnostics& diag_;
    std::size_t pos_ = 0;
    bool pcl_mode_ = false;  ///< inside PCL (after ESC %#A): skip until the next escape
    char terminator_ = '\x03';
    bool saw_hpgl_ = false;
    std::size_t stray_runs_ = 0;
    std::size_t first_stray_ = 0;
};

}  // namespace dtm::io::hpgl
