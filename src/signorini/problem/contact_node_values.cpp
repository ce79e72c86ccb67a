#include "signorini/problem/contact_node_values.hpp"

#include "signorini/contact/distributed_engine.hpp"

namespace signorini {

ContactNodeValues contact_node_values(const Model& model, const ContactResult& result) {
  const ContactSet& c = model.problem.contact;
  const int dim = model.mesh.dim();
  const Vector u = model.full_displacement(result);
  ContactNodeValues v;
  v.displacement = Eigen::MatrixXd::Zero(dim, c.size());
  if (!model.is_part()) {
    v.points.resize(dim, c.size());
    v.prescribed.resize(dim, c.size());
    for (Index j = 0; j < c.size(); ++j) {
      const Index node = c.nodes[static_cast<std::size_t>(j)];
      v.points.col(j) = model.mesh.node(node);
      v.prescribed.col(j) = model.dofs.prescribed_at(node);
      v.displacement.col(j) = u.segment(dim * node, dim);
    }
    return v;
  }
  v.points = model.whole.contact_points;
  v.prescribed = model.whole.contact_prescribed;
  for (Index j = 0; j < c.size(); ++j) {
    const Index node = model.local_node(c.nodes[static_cast<std::size_t>(j)]);
    if (node >= 0 && model.node_rank(node) == model.problem.rank)
      v.displacement.col(j) = u.segment(dim * node, dim);
  }
  sum_over_ranks(model.problem, v.displacement.data(), v.displacement.size());
  return v;
}

}  // namespace signorini
