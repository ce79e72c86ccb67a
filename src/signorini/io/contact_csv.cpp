#include "signorini/io/contact_csv.hpp"

#include <fmt/format.h>

#include "signorini/core/error.hpp"

namespace signorini {

std::string contact_csv(const ContactResult& result, const Model& model) {
  if (model.mesh.dim() != 2)
    throw InputError("contact.csv: only 2D problems have a single tangential direction");
  const ContactSet& c = model.problem.contact;
  // result.u holds the free dofs only; clamped dofs are zero in the full, node-major vector.
  const Vector u = model.dofs.expand(result.u);
  std::string out = "x,y,u_n,u_t,pressure,gap,n_x,n_y,s,boundary\n";
  // s: the arc length along the contact nodes in their order (chords between consecutive nodes,
  // so along a quadratic edge through its middle node); the boundary's name, quoted as CSV wants
  // when it holds a comma or a quote.
  std::string name = model.contact_boundary;
  if (name.find_first_of(",\"\n") != std::string::npos) {
    std::string quoted = "\"";
    for (const char ch : name) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    name = quoted + "\"";
  }
  double s = 0.0;
  for (Index j = 0; j < c.size(); ++j) {
    const Index node = c.nodes[static_cast<std::size_t>(j)];
    if (j > 0)
      s += (model.mesh.node(node) - model.mesh.node(c.nodes[static_cast<std::size_t>(j - 1)]))
               .norm();
    const double ux = u(2 * node);
    const double uy = u(2 * node + 1);
    const double nx = c.normals(0, j);
    const double ny = c.normals(1, j);
    const auto x = model.mesh.node(node);
    out += fmt::format(
        "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{}\n", x(0), x(1),
        ux * nx + uy * ny, -ux * ny + uy * nx, result.l(j), c.gaps(j), nx + 0.0, ny + 0.0, s, name);
  }
  return out;
}

}  // namespace signorini
