#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <geometry/gmp_pool.hpp>

// The tests run with GMP's pool in place, as the genbsp tool does.
int main(int argc, char* argv[]) {
  geometry::use_gmp_pool();
  return Catch::Session().run(argc, argv);
}
