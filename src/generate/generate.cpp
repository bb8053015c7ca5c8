#include "bimdf/generate.hpp"

#include <stdexcept>

#include "generate/generators.hpp"

namespace bimdf {

std::vector<std::string> generator_family_names() { return {"random", "quadwild"}; }

Problem generate_problem(const std::string& family, int64_t size, uint64_t seed) {
  if (size < 1) throw std::invalid_argument("size must be >= 1, got " + std::to_string(size));
  if (family == "random") return detail::generate_random_network(size, seed);
  if (family == "quadwild") return detail::generate_quadwild_like(size, seed);
  throw std::invalid_argument("unknown generator family \"" + family +
                              "\" (expected random or quadwild)");
}

}  // namespace bimdf
