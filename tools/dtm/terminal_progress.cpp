// SPDX-License-Identifier: MIT
// Terminal progress for the dtm subcommands: a redrawn bar on a terminal, one line per stage in
// logs, nothing when quiet; Ctrl-C becomes a cancellation request (exit 130 in main.cpp).
#include "terminal_progress.hpp"

#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

namespace dtm::cli {
namespace {

volatile std::sig_atomic_t interrupted = 0;

extern "C" void on_interrupt(int) {
    interrupted = 1;
    std::signal(SIGINT, SIG_DFL);  // a second Ctrl-C ends the process at once
}

void install_interrupt_handler() {
    static const bool installed = [] {
        // Keep SIGINT ignored where the parent ignored it (background jobs, nohup).
        if (std::signal(SIGINT, on_interrupt) == SIG_IGN) std::signal(SIGINT, SIG_IGN);
        return true;
    }();
    (void)installed;
}

enum class Mode { quiet, lines, bar };

Mode detect_mode(bool quiet) {
    if (quiet) return Mode::quiet;
    const char* term = std::getenv("TERM");
    const bool dumb = term != nullptr && std::string(term) == "dumb";
    return ::isatty(STDERR_FILENO) != 0 && !dumb ? Mode::bar : Mode::lines;
}

/// What the callback draws; shared by every copy of the Progress handle. Calls are already
/// serialised by Progress, so no lock here.
class Display {
public:
    Display(Mode mode, std::string label) : mode_(mode), label_(std::move(label)) {}
    Display(const Display&) = delete;
    Display& operator=(const Display&) = delete;
    ~Display() {
        if (line_open_) std::fputc('\n', stderr);
    }

    bool update(double fraction, std::string_view what) {
        const bool new_stage = !what.empty() && what != stage_;
        if (new_stage) stage_.assign(what);
        if (mode_ == Mode::lines && new_stage) print_stage_line(fraction);
        if (mode_ == Mode::bar) draw_bar(fraction, new_stage);
        return interrupted == 0;
    }

private:
    void print_stage_line(double fraction) const {
        std::fprintf(stderr, "%s [%3d%%] %s\n", label_.c_str(), percent(fraction), stage_.c_str());
    }

    void draw_bar(double fraction, bool new_stage) {
        const auto now = std::chrono::steady_clock::now();
        const bool done = fraction >= 1.0;
        if (!new_stage && !done && line_open_ &&
            now - last_draw_ < std::chrono::milliseconds(100)) {
            return;
        }
        last_draw_ = now;
        constexpr int width = 30;
        const int filled = percent(fraction) * width / 100;
        std::string bar(static_cast<std::size_t>(filled), '#');
        bar.append(static_cast<std::size_t>(width - filled), '.');
        std::string stage = stage_.size() > 40 ? stage_.substr(0, 37) + "..." : stage_;
        stage.resize(40, ' ');
        std::fprintf(stderr, "\r\033[K%s %s [%s] %3d%%", label_.c_str(), stage.c_str(), bar.c_str(),
                     percent(fraction));
        line_open_ = !done;
        if (done) std::fputc('\n', stderr);
        std::fflush(stderr);
    }

    static int percent(double fraction) {
        const double clamped = fraction < 0.0 ? 0.0 : (fraction > 1.0 ? 1.0 : fraction);
        return static_cast<int>(clamped * 100.0);
    }

    Mode mode_;
    std::string label_;
    std::string stage_;
    bool line_open_ = false;
    std::chrono::steady_clock::time_point last_draw_{};
};

Progress make_progress(std::string label, bool quiet) {
    install_interrupt_handler();
    auto display = std::make_shared<Display>(detect_mode(quiet), std::move(label));
    return Progress([display](double fraction, std::string_view what) {
        return display->update(fraction, what);
    });
}

}  // namespace

Progress terminal_progress(bool quiet) { return make_progress("dtm:", quiet); }

Progress terminal_progress(const char* command, bool quiet) {
    std::string label = "dtm ";
    label += command;
    label += ':';
    return make_progress(std::move(label), quiet);
}

}  // namespace dtm::cli
