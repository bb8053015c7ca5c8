// libFuzzer: parse_flow (text integers, JSON arrays, solution objects) on arbitrary bytes; a
// parsed flow is then checked against a small problem, which must never crash whatever its size.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "bimdf/flow.hpp"
#include "round_trip.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bimdf::Problem problem = bimdf::parse_bimdf(
      "# bimdf-format 1\n2\n2 0\n2\n0 1 1 1 0 inf A 2 1\n1 1 0 0 0 5 Q 0 0.5\n", "<fixed>");
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<int64_t> flow;
  try {
    flow = bimdf::parse_flow(text, "<fuzz>");
  } catch (const bimdf::InputError&) {
    return 0;
  }
  const bimdf::FlowCheck check = bimdf::check_flow(problem, flow);
  bimdf::fuzz::require(check.size_ok == (flow.size() == 2), "size check agrees");
  return 0;
}
