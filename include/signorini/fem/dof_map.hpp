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

  /// Marks a component of a node as clamped (u = 0). Call before finalize().
  void clamp(Index node, int component);
  /// Marks a component as prescribed, u = value (a clamp with nonzero data). Call before
  /// finalize().
  void prescribe(Index node, int component, double value);
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

  /// The prescribed value of a clamped dof (0 for a plain clamp, and for free dofs).
  [[nodiscard]] double value(Index node, int component) const {
    return values_.size() == 0 ? 0.0 : values_(node * dim_ + component);
  }
  /// True if some clamped dof has a nonzero prescribed value.
  [[nodiscard]] bool has_prescribed_values() const { return values_.size() != 0; }
  /// The prescribed values on the full dofs (zero at free and plainly clamped dofs): u_D.
  [[nodiscard]] Vector prescribed_values() const;
  /// Full displacement (num_dofs) from a free vector: the free values, and the prescribed values
  /// (u_D, zero for plain clamps) at the clamped dofs.
  [[nodiscard]] Vector expand(const Vector& free_values) const;
  /// Free vector from a full vector.
  [[nodiscard]] Vector restrict_to_free(const Vector& full_values) const;

 private:
  Index num_nodes_;
  int dim_;
  Index num_free_ = 0;
  bool finalized_ = false;
  std::vector<Index> free_;  // per full dof: free number, or -1 (clamped)
  Vector values_;            // per full dof: the prescribed value; empty while all are 0
};

}  // namespace signorini
