#include "bimdf/solution.hpp"

namespace bimdf {

std::string_view status_name(SolveStatus status) {
  switch (status) {
    case SolveStatus::Optimal:
      return "optimal";
    case SolveStatus::Feasible:
      return "feasible";
    case SolveStatus::Infeasible:
      return "infeasible";
    case SolveStatus::Unbounded:
      return "unbounded";
  }
  return "unknown";
}

}  // namespace bimdf
