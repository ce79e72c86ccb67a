#include "signorini/fem/nodal_stress.hpp"

#include <cmath>

#include "signorini/fem/cell_threads.hpp"
#include "signorini/fem/elasticity_matrices.hpp"
#include "signorini/fem/isoparametric_element.hpp"

namespace signorini {

double von_mises_stress(double sxx, double syy, double szz, double sxy, double syz, double sxz) {
  const double d =
      (sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx);
  return std::sqrt(0.5 * d + 3.0 * (sxy * sxy + syz * syz + sxz * sxz));
}

namespace {

template <int Dim>
NodalStress nodal_stress_of(const Mesh& mesh, const ElasticityOptions& options,
                            const Vector& u_full) {
  const std::vector<ElasticityMatrixOf<Dim>> region_D =
      region_elasticity_matrices<Dim>(mesh, options);
  const bool plane_strain = options.plane_model == PlaneModel::PlaneStrain;
  NodalStress out;
  out.sigma = Eigen::MatrixXd::Zero(6, mesh.num_nodes());
  Vector count = Vector::Zero(mesh.num_nodes());
  // In parallel over shares of the nodes: thread t sums the stresses at its own nodes from every
  // cell that has one, in the cells' order, so no two threads write one node and any number of
  // threads gives one thread's sums to the bit.
  const int threads = cell_loop_threads(mesh.num_cells());
  const auto owner = [&](Index v) { return share_of(v, mesh.num_nodes(), threads); };
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    const int t = thread_number();
    ElementVectorOf<Dim> ue;
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      const auto nodes = mesh.cell(c);
      bool mine = false;
      for (const Index v : nodes) mine = mine || owner(v) == t;
      if (!mine) continue;
      const CellType type = mesh.cell_type(c);
      const auto n = static_cast<int>(nodes.size());
      const CellCoordinatesOf<Dim> X = cell_coordinates<Dim>(mesh, c);
      const ElasticityMatrixOf<Dim>& D = region_D[static_cast<std::size_t>(mesh.cell_region(c))];
      const double nu = material_of_region(options, mesh.cell_region(c)).nu;
      ue.resize(Dim * n);
      for (int a = 0; a < n; ++a)
        for (int k = 0; k < Dim; ++k)
          ue(Dim * a + k) = u_full(Dim * nodes[static_cast<std::size_t>(a)] + k);
      // The strain of the cell at each of its nodes (the cell's own polynomial, not a recovery).
      for (int a = 0; a < n; ++a) {
        const Index v = nodes[static_cast<std::size_t>(a)];
        if (owner(v) != t) continue;
        double det_j = 0.0;
        const StrainMatrixOf<Dim> B = strain_matrix<Dim>(type, X, reference_node(type, a), det_j);
        const Eigen::Matrix<double, ElementSizes<Dim>::kStrains, 1> s = D * (B * ue);
        if constexpr (Dim == 2) {
          out.sigma(0, v) += s(0);
          out.sigma(1, v) += s(1);
          out.sigma(2, v) += plane_strain ? nu * (s(0) + s(1)) : 0.0;
          out.sigma(3, v) += s(2);
        } else {  // Voigt (xx, yy, zz, yz, xz, xy) to (xx, yy, zz, xy, yz, xz)
          out.sigma(0, v) += s(0);
          out.sigma(1, v) += s(1);
          out.sigma(2, v) += s(2);
          out.sigma(3, v) += s(5);
          out.sigma(4, v) += s(3);
          out.sigma(5, v) += s(4);
        }
        count(v) += 1.0;
      }
    }
  }
  out.von_mises.resize(mesh.num_nodes());
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    if (count(n) > 0.0) out.sigma.col(n) /= count(n);
    const auto s = out.sigma.col(n);
    out.von_mises(n) = von_mises_stress(s(0), s(1), s(2), s(3), s(4), s(5));
  }
  return out;
}

}  // namespace

NodalStress nodal_stress(const Mesh& mesh, const ElasticityOptions& options, const Vector& u_full) {
  require_supported_cells(mesh);
  return mesh.dim() == 2 ? nodal_stress_of<2>(mesh, options, u_full)
                         : nodal_stress_of<3>(mesh, options, u_full);
}

}  // namespace signorini
