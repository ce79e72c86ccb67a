#include "signorini/interface/tangent_basis.hpp"

#include <stdexcept>

namespace signorini {

Eigen::MatrixXd tangent_basis(const Eigen::VectorXd& nu) {
  if (nu.size() == 2) return Eigen::Vector2d(-nu(1), nu(0));
  if (nu.size() != 3) throw std::invalid_argument("tangent_basis: a normal of 2 or 3 components");
  const Eigen::Vector3d n = nu;
  Eigen::Index axis = 0;
  n.cwiseAbs().minCoeff(&axis);  // the axis least aligned with nu: never parallel to it
  const Eigen::Vector3d t1 = Eigen::Vector3d::Unit(axis).cross(n).normalized();
  Eigen::MatrixXd basis(3, 2);
  basis.col(0) = t1;
  basis.col(1) = n.cross(t1);
  return basis;
}

Eigen::MatrixXd cartesian_tangential(const Eigen::MatrixXd& normals,
                                     const Eigen::MatrixXd& tangential) {
  Eigen::MatrixXd out(normals.rows(), tangential.cols());
  for (Eigen::Index j = 0; j < tangential.cols(); ++j)
    out.col(j) = tangent_basis(normals.col(j)) * tangential.col(j);
  return out;
}

}  // namespace signorini
