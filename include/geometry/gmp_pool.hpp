/// @file
/// Per-thread free lists for GMP's small limb arrays.
///
/// Exact arithmetic on GMP makes and drops many short-lived numbers of a few
/// limbs: every product and sum without expression templates is a fresh
/// `mpz_t` whose limbs come from `malloc`.  `use_gmp_pool()` puts a free list
/// per size (8 to 256 bytes, in steps of 8: one to 32 limbs) and per thread in
/// front of the allocator GMP had, so that most of those allocations are a
/// pointer taken off a list.  Larger blocks, and blocks past a list's cap, go
/// to that allocator as before.
///
/// Every block still comes from, and at last goes back to, the allocator GMP
/// had when the pool was put in place: GMP passes the size of a block when it
/// frees it, and a list holds blocks of exactly its size, so a block made
/// before the pool was put in place is reused or returned correctly too.
#pragma once

#include <gmp.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace geometry {

namespace detail::gmp_pool {

inline constexpr std::size_t step = 8;        ///< bytes: one 64-bit limb
inline constexpr std::size_t classes = 32;    ///< block sizes 8, 16, …, 256 bytes
inline constexpr std::uint32_t capacity = 512; ///< blocks kept per size and thread (at most about 2 MB a thread)

using allocate_fn = void* (*)(std::size_t);
using reallocate_fn = void* (*)(void*, std::size_t, std::size_t);
using free_fn = void (*)(void*, std::size_t);

/// The functions GMP had before the pool (the fallback for every block).
struct previous_functions {
  allocate_fn allocate = nullptr;
  reallocate_fn reallocate = nullptr;
  free_fn release = nullptr;
};
inline previous_functions& previous() noexcept {
  static previous_functions p;
  return p;
}

struct block {
  block* next;
};

/// One thread's lists (trivial, so that reaching them costs no guard).
struct lists {
  std::array<block*, classes> head;
  std::array<std::uint32_t, classes> count;
  bool tracked; ///< the thread gives its blocks back when it ends
  bool closed;  ///< it has: blocks go straight to the previous allocator
};
inline lists& local() noexcept {
  static thread_local constinit lists l{};
  return l;
}

/// Gives a thread's blocks back to the previous allocator when it ends.
struct closer {
  closer(closer const&) = delete;
  closer& operator=(closer const&) = delete;
  closer() = default;
  ~closer() {
    lists& l = local();
    l.closed = true;
    for (std::size_t c = 0; c < classes; ++c)
      while (block* b = l.head[c]) {
        l.head[c] = b->next;
        previous().release(b, (c + 1) * step);
      }
    l.count = {};
  }
};
inline void track(lists& l) {
  static thread_local closer c;
  (void)c;
  l.tracked = true;
}

/// The list for blocks of `n` bytes, or `classes` for none.
constexpr std::size_t class_of(std::size_t n) noexcept {
  return n != 0 && n <= classes * step && n % step == 0 ? n / step - 1 : classes;
}

inline void* allocate(std::size_t n) {
  if (std::size_t c = class_of(n); c < classes) {
    lists& l = local();
    if (block* b = l.head[c]) {
      l.head[c] = b->next;
      --l.count[c];
      return b;
    }
  }
  return previous().allocate(n);
}

inline void release(void* p, std::size_t n) {
  if (std::size_t c = class_of(n); c < classes) {
    lists& l = local();
    if (l.count[c] < capacity && !l.closed) {
      if (!l.tracked) track(l);
      auto* b = static_cast<block*>(p);
      b->next = l.head[c];
      l.head[c] = b;
      ++l.count[c];
      return;
    }
  }
  previous().release(p, n);
}

inline void* reallocate(void* p, std::size_t old_size, std::size_t new_size) {
  if (old_size == new_size) return p;
  if (class_of(old_size) == classes && class_of(new_size) == classes) return previous().reallocate(p, old_size, new_size);
  void* q = allocate(new_size);
  std::memcpy(q, p, old_size < new_size ? old_size : new_size);
  release(p, old_size);
  return q;
}

} // namespace detail::gmp_pool

/// Puts per-thread free lists in front of GMP's allocator (see the file's
/// comment).  Call it at the start of `main`, before other threads use GMP;
/// calling it again does nothing (`gmp_pool_in_use()` tells).
///
/// GMP's memory functions are global to the process, so a library never
/// calls this on its own: the `genbsp` tool, the benchmarks and the tests do.
inline void use_gmp_pool() noexcept {
  namespace p = detail::gmp_pool;
  p::allocate_fn a = nullptr;
  p::reallocate_fn r = nullptr;
  p::free_fn f = nullptr;
  mp_get_memory_functions(&a, &r, &f);
  if (a == &p::allocate) return;
  p::previous() = {a, r, f};
  mp_set_memory_functions(&p::allocate, &p::reallocate, &p::release);
}

/// Whether GMP allocates through the pool.
inline bool gmp_pool_in_use() noexcept {
  void* (*a)(std::size_t) = nullptr;
  mp_get_memory_functions(&a, nullptr, nullptr);
  return a == &detail::gmp_pool::allocate;
}

} // namespace geometry
