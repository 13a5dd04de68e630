#pragma once
// A number of an exported text file, as its reader takes it: the whole word, finite.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <string>

namespace aerobreak::testing {

inline double finite_number(const std::string& word) {
  char* end = nullptr;
  const double value = std::strtod(word.c_str(), &end);
  INFO(word);
  REQUIRE(*end == '\0');
  REQUIRE(std::isfinite(value));
  return value;
}

}  // namespace aerobreak::testing
