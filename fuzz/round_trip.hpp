// What every parser harness checks once a parse succeeds: the problem is valid, and writing it
// in either format and reading it back gives the same problem. Any other exception than
// bimdf::InputError, or a failed check, aborts — libFuzzer records the input as a crash.
#pragma once

#include <cstdlib>
#include <cstdio>

#include "bimdf/io.hpp"

namespace bimdf::fuzz {

inline void require(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz check failed: %s\n", what);
    std::abort();
  }
}

inline void check_round_trips(const Problem& p) {
  require(!validate(p).has_value(), "a parsed problem is valid");
  Problem unnamed = p;  // the .bimdf format has no names
  unnamed.node_name.clear();
  unnamed.edge_name.clear();
  require(parse_bimdf(to_bimdf(p), "<rewritten>") == unnamed, ".bimdf write/read round-trip");
  require(parse_json_problem(to_json_problem(p), "<rewritten>") == p, "JSON write/read round-trip");
}

}  // namespace bimdf::fuzz
