// Builds a problem through the public API, round-trips it through the .bimdf format and
// verifies a flow: enough to prove headers, library and package config fit together.
#include <bimdf/flow.hpp>
#include <bimdf/io.hpp>
#include <iostream>
#include <vector>

int main() {
  // Two nodes with demand 2 joined by a head-head edge: x = 2 satisfies both.
  bimdf::Problem p;
  p.add_node(2);
  p.add_node(2);
  p.add_edge({0, true}, bimdf::End{1, true}, 0, bimdf::kInfinity,
             bimdf::Cost::quad_deviation(1.5, 2));
  const bimdf::Problem q = bimdf::parse_bimdf(bimdf::to_bimdf(p), "consumer");
  const std::vector<int64_t> flow = {2};
  const bimdf::FlowCheck check = bimdf::check_flow(q, flow);
  std::cout << "nodes " << q.num_nodes() << " edges " << q.num_edges() << " objective "
            << check.objective << " feasible " << check.feasible() << "\n";
  return q == p && check.feasible() ? 0 : 1;
}
