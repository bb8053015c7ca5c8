// The generator families behind bimdf/generate.hpp, one file each.
#pragma once

#include <cstdint>

#include "bimdf/problem.hpp"
#include "generate/random_source.hpp"

namespace bimdf::detail {

Problem generate_random_network(int64_t size, uint64_t seed);
Problem generate_quadwild_like(int64_t size, uint64_t seed);

}  // namespace bimdf::detail
