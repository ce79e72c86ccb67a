#include "signorini/output/solution_vtu.hpp"

#include <map>

#include "signorini/contact/friction_law.hpp"
#include "signorini/core/error.hpp"
#include "signorini/fem/nodal_stress.hpp"
#include "signorini/interface/tangent_basis.hpp"
#include "signorini/output/vtu_file.hpp"

namespace signorini {

namespace {

std::uint8_t flag(bool b) {
  return b ? std::uint8_t{1} : std::uint8_t{0};
}

// The point data of solution.vtu on every node of the mesh, made once for the whole file and
// any of its pieces (the nodal stresses are the costly part).
struct NodalFields {
  Vector u;  // the full node-major displacement, clamped dofs 0
  NodalStress stress;
  std::vector<double> pressure, gap;
  std::vector<std::uint8_t> active, on_boundary;
};

NodalFields nodal_fields(const ContactResult& result, const Model& model) {
  const Index n = model.mesh.num_nodes();
  NodalFields f;
  f.u = model.full_displacement(result);
  f.stress = nodal_stress(model.mesh, model.elasticity, f.u);  // YZ, XZ are 0 in 2D
  f.pressure.assign(static_cast<std::size_t>(n), 0.0);
  f.gap.assign(static_cast<std::size_t>(n), 0.0);
  f.active.assign(static_cast<std::size_t>(n), 0);
  f.on_boundary.assign(static_cast<std::size_t>(n), 0);
  const ContactSet& c = model.problem.contact;
  for (Index j = 0; j < c.size(); ++j) {
    // (The contact set names the whole mesh's nodes; a rank's part has some of them.)
    const Index local = model.local_node(c.nodes[static_cast<std::size_t>(j)]);
    if (local < 0) continue;
    const auto node = static_cast<std::size_t>(local);
    f.pressure[node] = result.l(j);
    f.gap[node] = c.gaps(j);
    f.active[node] = flag(result.l(j) > 0.0);  // as SolveSummary::num_active counts them
    f.on_boundary[node] = 1;
  }
  return f;
}

// solution.vtu's content for the given cells (all: null), with the nodes that they use,
// renumbered in increasing order (all nodes when all cells).
VtuFile solution_file(const NodalFields& f, const Model& model, const std::vector<Index>* cells) {
  const Mesh& mesh = model.mesh;
  const Index n = mesh.num_nodes();

  // The nodes of the piece and their numbers in it (-1: not in it).
  std::vector<Index> point_of(static_cast<std::size_t>(n), -1);
  std::vector<Index> nodes;
  if (cells == nullptr) {
    nodes.resize(static_cast<std::size_t>(n));
    for (Index k = 0; k < n; ++k)
      nodes[static_cast<std::size_t>(k)] = point_of[static_cast<std::size_t>(k)] = k;
  } else {
    std::vector<bool> used(static_cast<std::size_t>(n), false);
    for (const Index c : *cells)
      for (const Index k : mesh.cell(c)) used[static_cast<std::size_t>(k)] = true;
    for (Index k = 0; k < n; ++k)
      if (used[static_cast<std::size_t>(k)]) {
        point_of[static_cast<std::size_t>(k)] = static_cast<Index>(nodes.size());
        nodes.push_back(k);
      }
  }
  const auto m = static_cast<Index>(nodes.size());
  Eigen::MatrixXd points(mesh.dim(), m);
  for (Index p = 0; p < m; ++p)
    points.col(p) = mesh.coordinates().col(nodes[static_cast<std::size_t>(p)]);

  VtuFile vtu(points);
  const Index num_cells = cells == nullptr ? mesh.num_cells() : static_cast<Index>(cells->size());
  std::vector<std::int32_t> region(static_cast<std::size_t>(num_cells));
  std::vector<Index> renumbered;
  for (Index i = 0; i < num_cells; ++i) {
    const Index c = cells == nullptr ? i : (*cells)[static_cast<std::size_t>(i)];
    renumbered.clear();
    for (const Index k : mesh.cell(c)) renumbered.push_back(point_of[static_cast<std::size_t>(k)]);
    vtu.add_cell(mesh.cell_type(c), renumbered);
    region[static_cast<std::size_t>(i)] = mesh.cell_region(c);
  }
  // The region of each cell: its index in the mesh's region names (0: "", cells in no named
  // region; Gmsh's physical surfaces from 1 on, in the order of their tags).
  vtu.add_cell_data("region", region);

  const auto per_point = [&](int components, const auto& value_of) {
    std::vector<double> out(static_cast<std::size_t>(components * m));
    for (Index p = 0; p < m; ++p)
      for (int i = 0; i < components; ++i)
        out[static_cast<std::size_t>(components * p + i)] =
            value_of(nodes[static_cast<std::size_t>(p)], i);
    return out;
  };
  const int dim = mesh.dim();
  vtu.add_point_data("displacement", 3,
                     per_point(3, [&](Index k, int i) { return i < dim ? f.u(dim * k + i) : 0.0; }),
                     {"X", "Y", "Z"});
  vtu.add_point_data("stress", 6,
                     per_point(6, [&](Index k, int i) { return f.stress.sigma(i, k); }),
                     {"XX", "YY", "ZZ", "XY", "YZ", "XZ"});
  vtu.add_point_data("von_mises", 1,
                     per_point(1, [&](Index k, int) { return f.stress.von_mises(k); }));
  const auto bytes = [&](const std::vector<std::uint8_t>& all) {
    std::vector<std::uint8_t> out(static_cast<std::size_t>(m));
    for (Index p = 0; p < m; ++p)
      out[static_cast<std::size_t>(p)] =
          all[static_cast<std::size_t>(nodes[static_cast<std::size_t>(p)])];
    return out;
  };
  vtu.add_point_data("contact_pressure", 1, per_point(1, [&](Index k, int) {
                       return f.pressure[static_cast<std::size_t>(k)];
                     }));
  vtu.add_point_data(
      "gap", 1, per_point(1, [&](Index k, int) { return f.gap[static_cast<std::size_t>(k)]; }));
  vtu.add_point_data("contact_active", bytes(f.active));
  vtu.add_point_data("contact_boundary", bytes(f.on_boundary));
  return vtu;
}

}  // namespace

std::string solution_vtu(const ContactResult& result, const Model& model) {
  return solution_file(nodal_fields(result, model), model, nullptr).take_text();
}

std::string solution_vtu_piece(const ContactResult& result, const Model& model,
                               const std::vector<Index>& cells,
                               const std::vector<std::string>& pieces, std::string* pvtu) {
  VtuFile vtu = solution_file(nodal_fields(result, model), model, &cells);
  if (pvtu != nullptr) *pvtu = vtu.parallel_text(pieces);
  return vtu.take_text();
}

std::string contact_vtu(const ContactResult& result, const Model& model) {
  return contact_vtu(result, model, contact_node_values(model, result));
}

std::string contact_vtu(const ContactResult& result, const Model& model,
                        const ContactNodeValues& values) {
  const int dim = model.mesh.dim();
  const ContactSet& c = model.problem.contact;
  const Index m = c.size();
  VtuFile vtu(values.points);
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
    Eigen::Vector3d uj = Eigen::Vector3d::Zero(), nj = Eigen::Vector3d::Zero();
    uj.head(dim) = values.displacement.col(j);
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
  if (const ContactLaw& law = contact_law(model.problem); law.components() > 1) {
    // Friction: the tangential traction as a Cartesian vector (the tangential part of -sigma n,
    // as contact_pressure is its normal part) and the state (0 separated, 1 sticking, 2
    // sliding), as contact.csv has them.
    const std::vector<FrictionState> states = friction_states(law, result.l, result.tangential);
    const Matrix t = cartesian_tangential(c.normals, result.tangential);
    std::vector<double> traction(static_cast<std::size_t>(3 * m), 0.0);
    std::vector<std::uint8_t> state(static_cast<std::size_t>(m));
    for (Index j = 0; j < m; ++j) {
      const auto k = static_cast<std::size_t>(j);
      for (Index i = 0; i < dim; ++i) traction[3 * k + static_cast<std::size_t>(i)] = t(i, j);
      state[k] = static_cast<std::uint8_t>(states[k]);
    }
    vtu.add_point_data("tangential_traction", 3, traction, {"X", "Y", "Z"});
    vtu.add_point_data("friction_state", state);
  }
  return vtu.take_text();
}

}  // namespace signorini
