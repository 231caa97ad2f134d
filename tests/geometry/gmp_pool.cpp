#include <catch2/catch.hpp>

#include <geometry/gmp_pool.hpp>
#include <geometry/number.hpp>

#include <cstring>
#include <string>
#include <thread>
#include <vector>

using geometry::integer;
using geometry::rational;

namespace {

struct functions {
  void* (*allocate)(std::size_t) = nullptr;
  void* (*reallocate)(void*, std::size_t, std::size_t) = nullptr;
  void (*release)(void*, std::size_t) = nullptr;
  functions() { mp_get_memory_functions(&allocate, &reallocate, &release); }
};

// n! by repeated products: numbers from one limb to far past the pool's sizes.
integer factorial(int n) {
  integer r(1);
  for (int k = 2; k <= n; ++k) r *= k;
  return r;
}

} // namespace

TEST_CASE("GMP's allocations go through the pool, which reuses freed blocks of the same size", "[number][gmp_pool]") {
  geometry::use_gmp_pool();
  REQUIRE(geometry::gmp_pool_in_use());
  functions before;
  geometry::use_gmp_pool(); // twice: nothing changes (the pool is not its own fallback)
  functions f;
  REQUIRE(f.allocate == before.allocate);
  REQUIRE(geometry::detail::gmp_pool::previous().allocate != &geometry::detail::gmp_pool::allocate);
  REQUIRE(f.allocate == &geometry::detail::gmp_pool::allocate);
  REQUIRE(f.release == &geometry::detail::gmp_pool::release);

  // A block of a pooled size, freed, is the next one of that size.
  void* a = f.allocate(64);
  std::memset(a, 0xab, 64);
  f.release(a, 64);
  void* b = f.allocate(64);
  CHECK(b == a);
  // Another size does not take it.
  void* c = f.allocate(72);
  CHECK(c != a);
  f.release(c, 72);
  // Growing keeps the contents, across sizes, into and out of the pooled range.
  auto* bytes = static_cast<unsigned char*>(b);
  for (int k = 0; k < 64; ++k) bytes[k] = static_cast<unsigned char>(k);
  auto* grown = static_cast<unsigned char*>(f.reallocate(b, 64, 4096));
  for (int k = 0; k < 64; ++k) REQUIRE(grown[k] == k);
  auto* shrunk = static_cast<unsigned char*>(f.reallocate(grown, 4096, 16));
  for (int k = 0; k < 16; ++k) REQUIRE(shrunk[k] == k);
  f.release(shrunk, 16);
  // Odd and zero sizes are the previous allocator's.
  void* odd = f.allocate(13);
  f.release(odd, 13);
  // Past a list's capacity, blocks go back to the previous allocator (no
  // error, and the list still serves).
  auto& lists = geometry::detail::gmp_pool::local();
  std::vector<void*> drained; // the list of 24-byte blocks emptied first
  while (lists.count[2] != 0) drained.push_back(f.allocate(24));
  std::vector<void*> many;
  for (std::uint32_t k = 0; k < 2 * geometry::detail::gmp_pool::capacity; ++k) many.push_back(f.allocate(24));
  for (void* p : many) f.release(p, 24);
  CHECK(lists.count[2] == geometry::detail::gmp_pool::capacity);
  void* again = f.allocate(24);
  CHECK(again == many[geometry::detail::gmp_pool::capacity - 1]);
  f.release(again, 24);
  for (void* p : drained) f.release(p, 24);
}

TEST_CASE("Exact arithmetic is unchanged with the pool, in several threads at once", "[number][gmp_pool]") {
  geometry::use_gmp_pool();
  REQUIRE(geometry::gmp_pool_in_use());
  // 60! against its digits; 400! (2,886 bits: 46 limbs, past the pooled
  // sizes) divided back down to 1; sums of fractions.
  integer const f60("8320987112741390144276341183223364380754172606361245952449277696409600000000000000");
  REQUIRE(factorial(60) == f60);
  auto check = [] {
    for (int round = 0; round < 50; ++round) {
      integer big = factorial(400);
      for (int k = 400; k >= 2; --k) big /= k;
      if (big != 1) return false;
      rational sum(0);
      for (int k = 1; k <= 40; ++k) sum += rational(1, k * (k + 1)); // telescopes to 40/41
      if (sum != rational(40, 41)) return false;
    }
    return true;
  };
  std::vector<char> ok(4, 0);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < ok.size(); ++t) threads.emplace_back([&, t] { ok[t] = check(); });
  for (auto& t : threads) t.join();
  for (char o : ok) CHECK(o);
  CHECK(check());
}
