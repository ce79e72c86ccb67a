#include "signorini/interface/contact_tangents.hpp"

#include <Eigen/Geometry>
#include <stdexcept>
#include <vector>

namespace signorini {

SparseMatrix tangential_operator(const ContactSet& contact, const DofMap& dofs) {
  const int dim = dofs.dim();
  std::vector<Eigen::Triplet<double, int>> triplets;
  for (Index j = 0; j < contact.size(); ++j) {
    const Index node = contact.nodes[static_cast<std::size_t>(j)];
    Eigen::MatrixXd t = tangent_basis(contact.normals.col(j));
    if (dofs.has_frame(node)) t = dofs.frame(node).transpose() * t;  // as N's row (2D frames)
    for (int k = 0; k < dim - 1; ++k)
      for (int c = 0; c < dim; ++c) {
        const Index d = dofs.free_index(node, c);
        if (d >= 0)
          triplets.emplace_back(static_cast<int>((dim - 1) * j + k), static_cast<int>(d), t(c, k));
      }
  }
  SparseMatrix T((dim - 1) * contact.size(), dofs.num_free());
  T.setFromTriplets(triplets.begin(), triplets.end());
  return T;
}

}  // namespace signorini
