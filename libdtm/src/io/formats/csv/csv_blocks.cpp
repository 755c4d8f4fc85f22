// SPDX-License-Identifier: MIT
// Delimited text read in blocks: one buffer of about a block is filled, cut after its last line
// end, and what follows the cut is moved to the front before the next fill. A line longer than
// the buffer grows it (by a block at a time) until the line ends, so every block but the last
// ends with '\n' and no line is ever split between two blocks.
#include <algorithm>
#include <cstring>
#include <utility>

#include "csv_detail.hpp"

namespace dtm::io::csv {

Blocks::Blocks(Fill fill, std::size_t block_bytes, std::size_t input_bytes)
    : fill_(std::move(fill)),
      block_bytes_(std::max<std::size_t>(block_bytes, 1)),
      buffer_(input_bytes > 0 ? std::min(block_bytes_, input_bytes + 1) : block_bytes_, '\0') {}

std::string_view Blocks::next() {
    offset_ += cut_;
    std::memmove(buffer_.data(), buffer_.data() + cut_, end_ - cut_);
    end_ -= cut_;
    cut_ = 0;
    return cut_after(0);
}

std::string_view Blocks::extend() {
    if (!at_end()) buffer_.resize(buffer_.size() + block_bytes_);
    return cut_after(cut_);
}

/// Fills the buffer, growing it until a line ends at or after @p from (or the input ends), and
/// cuts after the last line end.
std::string_view Blocks::cut_after(std::size_t from) {
    for (;;) {
        while (!eof_ && end_ < buffer_.size()) {
            const std::size_t got = fill_(buffer_.data() + end_, buffer_.size() - end_);
            eof_ = got == 0;
            end_ += got;
        }
        if (eof_) {
            cut_ = end_;
            break;
        }
        const std::size_t nl = std::string_view(buffer_).substr(from, end_ - from).rfind('\n');
        if (nl != std::string_view::npos) {
            cut_ = from + nl + 1;
            break;
        }
        buffer_.resize(buffer_.size() + block_bytes_);  // a line longer than the buffer
    }
    return {buffer_.data(), cut_};
}

}  // namespace dtm::io::csv
