// SPDX-License-Identifier: MIT
/// @file
/// @brief An append-only array in fixed pages: growing never copies and never holds twice the
/// memory (as a doubling vector does), so a method's peak bytes are its real size.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

namespace dtm::methods::detail {

template <class T, int PageBits = 12>
class PagedArray {
public:
    static constexpr std::size_t page_size = std::size_t{1} << PageBits;

    [[nodiscard]] T& operator[](std::size_t i) noexcept {
        return pages_[i >> PageBits][i & (page_size - 1)];
    }
    [[nodiscard]] const T& operator[](std::size_t i) const noexcept {
        return pages_[i >> PageBits][i & (page_size - 1)];
    }
    void push_back(const T& value) {
        if ((size_ & (page_size - 1)) == 0) pages_.push_back(std::make_unique<T[]>(page_size));
        (*this)[size_++] = value;
    }
    [[nodiscard]] std::size_t size() const noexcept { return size_; }
    [[nodiscard]] std::size_t bytes() const noexcept {
        return pages_.size() * page_size * sizeof(T) + pages_.capacity() * sizeof(void*);
    }
    void clear() noexcept {
        pages_.clear();
        pages_.shrink_to_fit();
        size_ = 0;
    }

private:
    std::vector<std::unique_ptr<T[]>> pages_;
    std::size_t size_ = 0;
};

}  // namespace dtm::methods::detail
