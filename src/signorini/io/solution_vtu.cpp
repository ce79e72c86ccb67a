#include "signorini/io/solution_vtu.hpp"

#include <map>

#include "signorini/core/error.hpp"
#include "signorini/fem/nodal_stress.hpp"
#include "signorini/io/vtu_file.hpp"

namespace signorini {

namespace {

void require_2d(const Model& model, const char* file) {
  if (model.mesh.dim() != 2)
    throw InputError(std::string(file) + ": only 2D problems can be written so far");
}

// (u_x, u_y, u_z) per node (u_z = 0 in 2D), from the full node-major displacement.
std::vector<double> displacement_xyz(const Vector& u_full, Index num_nodes, int dim) {
  std::vector<double> out(static_cast<std::size_t>(3 * num_nodes), 0.0);
  for (Index n = 0; n < num_nodes; ++n)
    for (int k = 0; k < dim; ++k) out[static_cast<std::size_t>(3 * n + k)] = u_full(dim * n + k);
  return out;
}

std::uint8_t flag(bool b) {
  return b ? std::uint8_t{1} : std::uint8_t{0};
}

}  // namespace

std::string solution_vtu(const ContactResult& result, const Model& model) {
  const Mesh& mesh = model.mesh;
  const Index n = mesh.num_nodes();
  const Vector u = model.dofs.expand(result.u);  // clamped dofs are 0

  VtuFile vtu(mesh.coordinates());
  std::vector<std::int32_t> region(static_cast<std::size_t>(mesh.num_cells()));
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    vtu.add_cell(mesh.cell_type(c), mesh.cell(c));
    region[static_cast<std::size_t>(c)] = mesh.cell_region(c);
  }
  // The region of each cell: its index in the mesh's region names (0: "", cells in no named
  // region; Gmsh's physical surfaces from 1 on, in the order of their tags).
  vtu.add_cell_data("region", region);

  vtu.add_point_data("displacement", 3, displacement_xyz(u, n, mesh.dim()), {"X", "Y", "Z"});

  const NodalStress stress = nodal_stress(mesh, model.elasticity, u);
  std::vector<double> tensor(static_cast<std::size_t>(6 * n));  // YZ, XZ are 0 in 2D
  for (Index k = 0; k < n; ++k)
    for (int i = 0; i < 6; ++i) tensor[static_cast<std::size_t>(6 * k + i)] = stress.sigma(i, k);
  vtu.add_point_data("stress", 6, tensor, {"XX", "YY", "ZZ", "XY", "YZ", "XZ"});
  vtu.add_point_data("von_mises", 1,
                     std::vector<double>(stress.von_mises.data(), stress.von_mises.data() + n));

  const ContactSet& c = model.problem.contact;
  std::vector<double> pressure(static_cast<std::size_t>(n), 0.0);
  std::vector<double> gap(static_cast<std::size_t>(n), 0.0);
  std::vector<std::uint8_t> active(static_cast<std::size_t>(n), 0);
  std::vector<std::uint8_t> on_boundary(static_cast<std::size_t>(n), 0);
  for (Index j = 0; j < c.size(); ++j) {
    const auto node = static_cast<std::size_t>(c.nodes[static_cast<std::size_t>(j)]);
    pressure[node] = result.l(j);
    gap[node] = c.gaps(j);
    active[node] = flag(result.l(j) > 0.0);  // as SolveSummary::num_active counts them
    on_boundary[node] = 1;
  }
  vtu.add_point_data("contact_pressure", 1, pressure);
  vtu.add_point_data("gap", 1, gap);
  vtu.add_point_data("contact_active", active);
  vtu.add_point_data("contact_boundary", on_boundary);
  return vtu.text();
}

std::string contact_vtu(const ContactResult& result, const Model& model) {
  require_2d(model, "contact.vtu");
  const Mesh& mesh = model.mesh;
  const ContactSet& c = model.problem.contact;
  const Index m = c.size();
  const Vector u = model.dofs.expand(result.u);

  Eigen::MatrixXd points(2, m);
  for (Index j = 0; j < m; ++j) {
    const Index node = c.nodes[static_cast<std::size_t>(j)];
    points.col(j) = mesh.node(node);
  }
  VtuFile vtu(points);
  // The facets of the contact set itself, so that contact.vtu shows the boundary the solver used
  // (also for a contact set not made from spec.contact).
  for (const std::vector<Index>& facet : c.facets)
    vtu.add_cell(facet.size() == 3 ? VtkCellType::QuadraticEdge : VtkCellType::Line, facet);

  std::vector<double> displacement(static_cast<std::size_t>(3 * m), 0.0);
  std::vector<double> normal(static_cast<std::size_t>(3 * m), 0.0);
  std::vector<double> un(static_cast<std::size_t>(m)), ut(static_cast<std::size_t>(m));
  std::vector<double> pressure(static_cast<std::size_t>(m)), gap(static_cast<std::size_t>(m));
  std::vector<double> deformed_gap(static_cast<std::size_t>(m));
  std::vector<std::uint8_t> active(static_cast<std::size_t>(m));
  for (Index j = 0; j < m; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const Index node = c.nodes[k];
    const double ux = u(2 * node), uy = u(2 * node + 1);
    const double nx = c.normals(0, j), ny = c.normals(1, j);
    displacement[3 * k] = ux;
    displacement[3 * k + 1] = uy;
    normal[3 * k] = nx;
    normal[3 * k + 1] = ny;
    // As contact.csv: tau is nu turned a quarter counterclockwise.
    un[k] = ux * nx + uy * ny;
    ut[k] = -ux * ny + uy * nx;
    pressure[k] = result.l(j);
    gap[k] = c.gaps(j);
    deformed_gap[k] = c.gaps(j) - un[k];
    active[k] = flag(result.l(j) > 0.0);
  }
  vtu.add_point_data("displacement", 3, displacement, {"X", "Y", "Z"});
  vtu.add_point_data("normal", 3, normal, {"X", "Y", "Z"});
  vtu.add_point_data("normal_displacement", 1, un);
  vtu.add_point_data("tangential_displacement", 1, ut);
  vtu.add_point_data("contact_pressure", 1, pressure);
  vtu.add_point_data("gap", 1, gap);
  vtu.add_point_data("deformed_gap", 1, deformed_gap);
  vtu.add_point_data("contact_active", active);
  return vtu.text();
}

}  // namespace signorini
