#pragma once
// Numbering of the displacement unknowns. Dof (node, component) of the full vector is
// node * dim + component; clamped dofs (u = 0 on Gamma_D, method.md section 1) are eliminated, and
// the remaining "free" dofs are numbered consecutively in the same order, so that the reduced
// stiffness is SPD whenever Gamma_D holds the body (paper, after (14)).

#include <vector>

#include "signorini/core/types.hpp"

namespace signorini {

class DofMap {
 public:
  DofMap(Index num_nodes, int dim);

  /// Marks a component of a node as clamped. Call before finalize().
  void clamp(Index node, int component);
  /// Numbers the free dofs. Further clamp() calls are errors.
  void finalize();

  [[nodiscard]] int dim() const { return dim_; }
  [[nodiscard]] Index num_nodes() const { return num_nodes_; }
  [[nodiscard]] Index num_dofs() const { return num_nodes_ * dim_; }
  [[nodiscard]] Index num_free() const { return num_free_; }
  /// Free-dof number of (node, component), or -1 if clamped.
  [[nodiscard]] Index free_index(Index node, int component) const {
    return free_[static_cast<std::size_t>(node * dim_ + component)];
  }
  [[nodiscard]] bool is_clamped(Index node, int component) const {
    return free_index(node, component) < 0;
  }

  /// Full vector (num_dofs) from a free vector, with zeros at clamped dofs.
  [[nodiscard]] Vector expand(const Vector& free_values) const;
  /// Free vector from a full vector.
  [[nodiscard]] Vector restrict_to_free(const Vector& full_values) const;

 private:
  Index num_nodes_;
  int dim_;
  Index num_free_ = 0;
  bool finalized_ = false;
  std::vector<Index> free_;  // per full dof: free number, or -1 (clamped)
};

}  // namespace signorini
