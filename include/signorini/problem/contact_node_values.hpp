#pragma once
// What the contact result files (contact.csv, contact.vtu) say at each contact node besides the
// solver's values: where the node is, its whole displacement, and its prescribed displacement.
// From the whole mesh, or on a rank's part of it (docs/distributed.md, "The mesh in parts") from
// the ranks together: each gives the displacements of the contact nodes it accounts for
// (Model::node_rank), and the sum over the ranks has them all.

#include "signorini/contact/contact_solver.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {

struct ContactNodeValues {
  Eigen::MatrixXd points;        ///< dim x contact size: the node's coordinates
  Eigen::MatrixXd displacement;  ///< dim x contact size: u at the node, prescribed values too
  Eigen::MatrixXd prescribed;    ///< dim x contact size: DofMap::prescribed_at (factor 1)
};

/// The values of `result` at the contact nodes of `model`: a collective call where the model is
/// a rank's part (every rank calls it, each gets them all).
[[nodiscard]] ContactNodeValues contact_node_values(const Model& model,
                                                    const ContactResult& result);

}  // namespace signorini
