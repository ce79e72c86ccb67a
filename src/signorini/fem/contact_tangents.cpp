#include "signorini/fem/contact_tangents.hpp"

#include <Eigen/Geometry>
#include <stdexcept>
#include <vector>

namespace signorini {

namespace {

// T's rows, with each node's tangents first turned by `local` (its local axes, 2D frames).
SparseMatrix tangential_rows(const ContactSet& contact, int dim, Index num_free,
                             const std::function<Index(Index j, int c)>& free_index,
                             const std::function<void(Index j, Eigen::MatrixXd& t)>& local) {
  std::vector<Eigen::Triplet<double, int>> triplets;
  for (Index j = 0; j < contact.size(); ++j) {
    Eigen::MatrixXd t = tangent_basis(contact.normals.col(j));
    if (local) local(j, t);
    for (int k = 0; k < dim - 1; ++k)
      for (int c = 0; c < dim; ++c) {
        const Index d = free_index(j, c);
        if (d >= 0)
          triplets.emplace_back(static_cast<int>((dim - 1) * j + k), static_cast<int>(d), t(c, k));
      }
  }
  SparseMatrix T((dim - 1) * contact.size(), num_free);
  T.setFromTriplets(triplets.begin(), triplets.end());
  return T;
}

}  // namespace

SparseMatrix tangential_operator(const ContactSet& contact, const DofMap& dofs) {
  const auto node = [&](Index j) { return contact.nodes[static_cast<std::size_t>(j)]; };
  return tangential_rows(
      contact, dofs.dim(), dofs.num_free(),
      [&](Index j, int c) { return dofs.free_index(node(j), c); },
      [&](Index j, Eigen::MatrixXd& t) {
        if (dofs.has_frame(node(j))) t = dofs.frame(node(j)).transpose() * t;  // as N's row
      });
}

SparseMatrix tangential_operator(const ContactSet& contact, int dim, Index num_free,
                                 const std::function<Index(Index j, int c)>& free_index) {
  return tangential_rows(contact, dim, num_free, free_index, {});
}

}  // namespace signorini
