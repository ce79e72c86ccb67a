#include "signorini/problem/memory_estimate.hpp"

namespace signorini {

double estimated_memory_bytes(double num_nodes, LinearSolverType solver) {
  switch (solver) {
    case LinearSolverType::Cholmod:
      return 4096.0 * num_nodes;
    case LinearSolverType::ConjugateGradient:
      return 2048.0 * num_nodes;
    case LinearSolverType::Dense: {
      const double n = 2.0 * num_nodes;  // 2D: two unknowns per node
      return 2048.0 * num_nodes + 8.0 * n * n;
    }
  }
  return 4096.0 * num_nodes;
}

}  // namespace signorini
