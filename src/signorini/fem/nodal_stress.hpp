#pragma once
// Stresses at the nodes, averaged over the cells that share a node, and the von Mises stress
// (the paper's Figure 4).

#include "signorini/fem/elasticity_assembly.hpp"

namespace signorini {

struct NodalStress {
  /// 6 x num_nodes, in VTK's order for symmetric tensors: sigma_xx, sigma_yy, sigma_zz,
  /// sigma_xy, sigma_yz, sigma_xz. In 2D sigma_yz = sigma_xz = 0, and sigma_zz = nu (sigma_xx +
  /// sigma_yy) in plane strain and 0 in plane stress.
  Eigen::MatrixXd sigma;
  Vector von_mises;  ///< num_nodes
};

/// Evaluates the strain of every cell at each of its nodes from the full displacement vector
/// (num_dofs, node-major), converts it to stress and averages at each node.
NodalStress nodal_stress(const Mesh& mesh, const ElasticityOptions& options, const Vector& u_full);

/// von Mises stress of a stress tensor.
double von_mises_stress(double sxx, double syy, double szz, double sxy, double syz = 0.0,
                        double sxz = 0.0);

}  // namespace signorini
