#include "iteration_log.hpp"

#include <fmt/format.h>

namespace signorini::app {

std::string iteration_line(ContactMethod method, const IterationEvent& e) {
  const char* outer = method == ContactMethod::SemismoothNewton ? "newton" : "uzawa";
  if (e.kind == IterationEvent::Kind::Inner) {
    std::string line = fmt::format("  {} {}  gnm {}  active {}  residual {:.1e}  armijo {}", outer,
                                   e.outer, e.inner, e.active, e.residual, e.armijo);
    // (CG iterations of this Newton system, on the iterative paths; none where a repeated
    // active set ended GNM without a solve, or where a factor solved it.)
    if (e.linear_iterations > 0) line += fmt::format("  cg {}", e.linear_iterations);
    return line;
  }
  std::string line =
      fmt::format("{} {}: ||dl||/||l|| = {:.1e}, active {}", outer, e.outer, e.residual, e.active);
  if (method == ContactMethod::UzawaGnm) line += fmt::format(", gnm {}", e.inner);
  if (e.linear_iterations > 0) line += fmt::format(", cg {}", e.linear_iterations);
  return line;
}

nlohmann::json iteration_json(const IterationEvent& e) {
  const bool inner = e.kind == IterationEvent::Kind::Inner;
  return {{"event", "iteration"}, {"level", inner ? "inner" : "outer"},
          {"outer", e.outer},     {"inner", e.inner},
          {"active", e.active},   {"residual", e.residual},
          {"armijo", e.armijo},   {"linear_iterations", e.linear_iterations}};
}

}  // namespace signorini::app
