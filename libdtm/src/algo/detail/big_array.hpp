// SPDX-License-Identifier: MIT
/// @file
/// @brief Allocator for the kernel's large arrays: blocks of 2 MiB and more are mapped directly
/// and, on Linux, marked for transparent huge pages. The mesh is walked in a data-dependent order;
/// with 4 KiB pages most of those accesses miss the TLB and every first touch faults, with 2 MiB
/// pages both costs mostly disappear. Small blocks use the ordinary allocator.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <tbb/parallel_for.h>

namespace dtm::detail {

template <class T>
struct BigArrayAllocator {
    using value_type = T;
    static constexpr std::size_t huge = std::size_t{2} << 20;

    BigArrayAllocator() noexcept = default;
    template <class U>
    BigArrayAllocator(const BigArrayAllocator<U>&) noexcept  // NOLINT(google-explicit-constructor)
    {}

    T* allocate(std::size_t n) {
        const std::size_t bytes = n * sizeof(T);
#if defined(__linux__)
        if (bytes >= huge) {
            const std::size_t rounded = (bytes + huge - 1) / huge * huge;
            void* p = std::aligned_alloc(huge, rounded);
            if (p == nullptr) throw std::bad_alloc();
            madvise(p, rounded, MADV_HUGEPAGE);
            return static_cast<T*>(p);
        }
#endif
        if (void* p = std::malloc(bytes == 0 ? 1 : bytes)) return static_cast<T*>(p);
        throw std::bad_alloc();
    }
    void deallocate(T* p, std::size_t) noexcept { std::free(p); }

    /// resize(n) default-initialises: plain integers are left as they are, so a large array is
    /// not written once before its real contents (its pages are first touched where it is used,
    /// in parallel).
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }

    template <class U>
    bool operator==(const BigArrayAllocator<U>&) const noexcept {
        return true;
    }
};

/// A std::vector for the kernel's large arrays.
template <class T>
using BigArray = std::vector<T, BigArrayAllocator<T>>;

/// Reserves room for @p n elements in an ordinary std::vector (one that must keep the standard
/// allocator, such as the Tin's arrays) and, before anything touches that memory, marks its whole
/// 2 MiB pages for transparent huge pages: a large array then costs a few hundred page faults
/// instead of one per 4 KiB.
template <class T>
void reserve_huge(std::vector<T>& v, std::size_t n) {
    v.reserve(n);
#if defined(__linux__)
    constexpr std::uintptr_t huge = std::uintptr_t{2} << 20;
    const auto begin = reinterpret_cast<std::uintptr_t>(v.data() + v.size());
    const auto end = reinterpret_cast<std::uintptr_t>(v.data() + v.capacity());
    const std::uintptr_t first = (begin + huge - 1) / huge * huge;
    const std::uintptr_t last = end / huge * huge;
    if (last > first) {
        madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
    }
#endif
}

/// Touches the reserved, not yet used storage of @p v (one byte per 4 KiB page) on all threads,
/// before a std::vector's resize initialises it on one: the page faults (on a virtual machine
/// also the host's first touch of guest memory) are most of the cost of a fresh large array, and
/// they are spread over the threads this way. The kernel's 480 MB triangle array of 10^7 points,
/// two threads: 0.65-0.69 s to resize without, 0.28-0.60 s with.
template <class T>
void prefault_in_parallel(std::vector<T>& v) {
    constexpr std::size_t page = 4096;
    auto* const begin = reinterpret_cast<unsigned char*>(v.data() + v.size());
    const std::size_t bytes = (v.capacity() - v.size()) * sizeof(T);
    tbb::parallel_for(std::size_t{0}, (bytes + page - 1) / page,
                      [&](std::size_t i) { std::memset(begin + i * page, 0, 1); });
}

/// Makes @p v @p n copies of @p value in fresh storage, reserved for huge pages and faulted in on
/// all threads before the (serial) initialisation: for large arrays built from scratch.
template <class T>
void assign_fresh(std::vector<T>& v, std::size_t n, const T& value) {
    std::vector<T>().swap(v);
    reserve_huge(v, n);
    prefault_in_parallel(v);
    v.assign(n, value);
}

}  // namespace dtm::detail
