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
  std::string out = "x,y,u_n,u_t,pressure,gap,n_x,n_y\n";
  for (Index j = 0; j < c.size(); ++j) {
    const Index node = c.nodes[static_cast<std::size_t>(j)];
    const double ux = u(2 * node);
    const double uy = u(2 * node + 1);
    const double nx = c.normals(0, j);
    const double ny = c.normals(1, j);
    const auto x = model.mesh.node(node);
    out += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", x(0),
                       x(1), ux * nx + uy * ny, -ux * ny + uy * nx, result.l(j), c.gaps(j),
                       nx + 0.0, ny + 0.0);
  }
  return out;
}

}  // namespace signorini
