// libFuzzer: a problem parser on arbitrary bytes, then the round-trip checks of round_trip.hpp.
// Built twice (fuzz/CMakeLists.txt): BIMDF_FUZZ_PARSER is parse_bimdf or parse_json_problem.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "round_trip.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  bimdf::Problem p;
  try {
    p = bimdf::BIMDF_FUZZ_PARSER(text, "<fuzz>");
  } catch (const bimdf::InputError&) {
    return 0;
  }
  bimdf::fuzz::check_round_trips(p);
  return 0;
}
