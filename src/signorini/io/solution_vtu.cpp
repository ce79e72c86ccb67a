#include "signorini/io/solution_vtu.hpp"

#include <map>

#include "signorini/core/error.hpp"
#include "signorini/fem/nodal_stress.hpp"
#include "signorini/io/vtu_file.hpp"

namespace signorini {

namespace {

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
  return vtu.take_text();
}

std::string contact_vtu(const ContactResult& result, const Model& model) {
  const Mesh& mesh = model.mesh;
  const int dim = mesh.dim();
  const ContactSet& c = model.problem.contact;
  const Index m = c.size();
  const Vector u = model.dofs.expand(result.u);

  Eigen::MatrixXd points(dim, m);
  for (Index j = 0; j < m; ++j) points.col(j) = mesh.node(c.nodes[static_cast<std::size_t>(j)]);
  VtuFile vtu(points);
  // The facets of the contact set itself, so that contact.vtu shows the boundary the solver used
  // (also for a contact set not made from spec.contact): lines in 2D, faces in 3D (the Tri6 and
  // Quad9 node orders are VTK's).
  for (const std::vector<Index>& facet : c.facets) {
    if (dim == 2) {
      vtu.add_cell(facet.size() == 3 ? VtkCellType::QuadraticEdge : VtkCellType::Line, facet);
      continue;
    }
    switch (facet.size()) {
      case 3:
        vtu.add_cell(VtkCellType::Triangle, facet);
        break;
      case 4:
        vtu.add_cell(VtkCellType::Quad, facet);
        break;
      case 6:
        vtu.add_cell(VtkCellType::QuadraticTriangle, facet);
        break;
      default:
        vtu.add_cell(VtkCellType::BiquadraticQuad, facet);
    }
  }

  std::vector<double> displacement(static_cast<std::size_t>(3 * m), 0.0);
  std::vector<double> normal(static_cast<std::size_t>(3 * m), 0.0);
  std::vector<double> un(static_cast<std::size_t>(m));
  std::vector<double> ut(static_cast<std::size_t>(dim == 2 ? m : 3 * m));
  std::vector<double> pressure(static_cast<std::size_t>(m)), gap(static_cast<std::size_t>(m));
  std::vector<double> deformed_gap(static_cast<std::size_t>(m));
  std::vector<std::uint8_t> active(static_cast<std::size_t>(m));
  for (Index j = 0; j < m; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const Index node = c.nodes[k];
    Eigen::Vector3d uj = Eigen::Vector3d::Zero(), nj = Eigen::Vector3d::Zero();
    uj.head(dim) = u.segment(dim * node, dim);
    nj.head(dim) = c.normals.col(j);
    for (std::size_t i = 0; i < 3; ++i) {
      displacement[3 * k + i] = uj(static_cast<Index>(i));
      normal[3 * k + i] = nj(static_cast<Index>(i));
    }
    un[k] = uj.dot(nj);
    if (dim == 2) {  // as contact.csv: tau is nu turned a quarter counterclockwise
      ut[k] = -uj(0) * nj(1) + uj(1) * nj(0);
    } else {  // the tangential displacement vector u - u_n nu
      const Eigen::Vector3d t = uj - un[k] * nj;
      for (std::size_t i = 0; i < 3; ++i) ut[3 * k + i] = t(static_cast<Index>(i));
    }
    pressure[k] = result.l(j);
    gap[k] = c.gaps(j);
    deformed_gap[k] = c.gaps(j) - un[k];
    active[k] = flag(result.l(j) > 0.0);
  }
  vtu.add_point_data("displacement", 3, displacement, {"X", "Y", "Z"});
  vtu.add_point_data("normal", 3, normal, {"X", "Y", "Z"});
  vtu.add_point_data("normal_displacement", 1, un);
  if (dim == 2)
    vtu.add_point_data("tangential_displacement", 1, ut);
  else
    vtu.add_point_data("tangential_displacement", 3, ut, {"X", "Y", "Z"});
  vtu.add_point_data("contact_pressure", 1, pressure);
  vtu.add_point_data("gap", 1, gap);
  vtu.add_point_data("deformed_gap", 1, deformed_gap);
  vtu.add_point_data("contact_active", active);
  return vtu.take_text();
}

}  // namespace signorini
