// SPDX-License-Identifier: MIT
// The dtm binary's global operator new: malloc, and for blocks of 2 MiB and more a
// madvise(MADV_HUGEPAGE) on their whole pages before anything touches them.
//
// Why: on the machines dtm runs on (VMs with transparent huge pages in "madvise" mode), first
// touch of fresh 4 KiB pages is a large part of every product's time: one page fault per 4 KiB,
// each costly under virtualisation (perf: 15-20 % of `dtm grid` in the fault path). A 2 MiB page
// takes one fault instead of 512. libdtm's BigArray does the same for its arrays; this covers the
// std::vector and TBB allocations of the rest. It is what glibc's tunable glibc.malloc.hugetlb=1
// does for mmap'd chunks, done here because a program cannot set its own tunables. Memory is
// freed by free() as usual; nothing else changes. See docs/adr/0007-huge-pages-for-large-blocks.md.
#include <malloc.h>
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <new>

#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
namespace {

constexpr std::size_t huge_page = std::size_t{2} << 20;

void advise_huge(void* p, std::size_t size) noexcept {
    if (p == nullptr || size < huge_page) return;
    const auto begin = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t first = (begin + huge_page - 1) & ~(huge_page - 1);
    const std::uintptr_t last = (begin + size) & ~(huge_page - 1);
    if (last > first) {
        madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
    }
}

void* allocate(std::size_t size) {
    void* p = std::malloc(size == 0 ? 1 : size);
    if (p == nullptr) throw std::bad_alloc();
    advise_huge(p, size);
    return p;
}

void* allocate_aligned(std::size_t size, std::align_val_t align) {
    const auto a = static_cast<std::size_t>(align);
    const std::size_t rounded = (size + a - 1) / a * a;
    void* p = std::aligned_alloc(a, rounded == 0 ? a : rounded);
    if (p == nullptr) throw std::bad_alloc();
    advise_huge(p, size);
    return p;
}

}  // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return allocate(size);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return allocate(size);
    } catch (...) {
        return nullptr;
    }
}
void* operator new(std::size_t size, std::align_val_t align) {
    return allocate_aligned(size, align);
}
void* operator new[](std::size_t size, std::align_val_t align) {
    return allocate_aligned(size, align);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
#endif

// The products' and analyses' policy (main.cpp calls it for them): freed memory stays in the
// process (no trimming of the heap's top, which grows in steps of 256 MiB), so the next phase's
// buffers reuse pages that are already mapped instead of faulting in fresh ones.
void keep_freed_memory() noexcept {
#ifdef M_TRIM_THRESHOLD
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_TOP_PAD, 256 << 20);
#endif
}
