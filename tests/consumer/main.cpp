// Compiles against the installed headers and checks one exact computation.
#include <geometry/number.hpp>

int main() {
  auto third = geometry::parse_number<geometry::rational>("1/3");
  return third * 3 == 1 ? 0 : 1;
}
