#pragma once
// Numbering of the displacement unknowns. Dof (node, component) of the full vector is
// node * dim + component; clamped dofs (u = 0 on Gamma_D, method.md section 1) are eliminated, and
// the remaining "free" dofs are numbered consecutively, node by node (in the nodes' order, or in
// a given order of the nodes), so that the reduced stiffness is SPD whenever Gamma_D holds the
// body (paper, after (14)).
//
// A node may have local axes (a frame, 2D only): its components are then those along the frame's
// columns, so that the normal component of a node on a curved boundary can be held alone
// ([[displacement]] normal). Full vectors (expand, restrict_to_free, prescribed_values) are always
// Cartesian; the free dofs, value() and is_clamped() are in the node's frame.

#include <functional>
#include <utility>
#include <vector>

#include "signorini/core/types.hpp"

namespace signorini {

class DofMap {
 public:
  DofMap(Index num_nodes, int dim);
  /// A numbering given whole, finalized: per dof (node * dim + component) its free number or -1,
  /// `num_free` free dofs in all (more than `free` numbers where the nodes are part of a larger
  /// mesh: problem/model_part.hpp); per dof the prescribed value (`values`, empty: all 0); the
  /// nodes with local axes and their axes (`frames`).
  DofMap(int dim, std::vector<Index> free, Index num_free, Vector values = {},
         const std::vector<std::pair<Index, Eigen::Matrix2d>>& frames = {});

  /// The numbering of `nodes` (increasing) alone, with their free numbers, prescribed values and
  /// axes: node i of the result is nodes[i]. num_free() stays that of the whole.
  [[nodiscard]] DofMap part(const std::vector<Index>& nodes) const;

  /// Gives a node local axes: the columns of Q (orthonormal), its components from now on those
  /// along them. Call before clamping the node's components, and before finalize().
  void set_frame(Index node, const Eigen::Matrix2d& Q);
  [[nodiscard]] bool has_frames() const { return !frame_of_.empty(); }
  [[nodiscard]] bool has_frame(Index node) const {
    return !frame_of_.empty() && frame_of_[static_cast<std::size_t>(node)] >= 0;
  }
  /// The node's local axes as columns (the identity without a frame).
  [[nodiscard]] Eigen::Matrix2d frame(Index node) const;
  /// The prescribed displacement of a node, Cartesian, dim entries (its clamped components'
  /// values along their axes; zero for a free node).
  [[nodiscard]] Eigen::VectorXd prescribed_at(Index node) const;

  /// Marks a component of a node as clamped (u = 0). Call before finalize().
  void clamp(Index node, int component);
  /// Marks a component as prescribed, u = value (a clamp with nonzero data). Call before
  /// finalize().
  void prescribe(Index node, int component, double value);
  /// Numbers the free dofs, node by node in the order of the nodes (or of `node_order`, a
  /// permutation of the nodes: e.g. one that keeps neighbours close in memory,
  /// fem/node_ordering.hpp). Further clamp() calls are errors.
  void finalize(const std::vector<Index>& node_order = {});

  /// The node's place in the numbering of the free dofs (the node itself without a node order;
  /// in a given numbering its first free number): a node's free dofs come after those of every
  /// node of lower place.
  [[nodiscard]] Index node_place(Index node) const {
    return place_.empty() ? node : place_[static_cast<std::size_t>(node)];
  }
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

  /// The prescribed value of a clamped dof (0 for a plain clamp, and for free dofs), along the
  /// node's axis `component`.
  [[nodiscard]] double value(Index node, int component) const {
    return values_.size() == 0 ? 0.0 : values_(node * dim_ + component);
  }
  /// True if some clamped dof has a nonzero prescribed value.
  [[nodiscard]] bool has_prescribed_values() const { return values_.size() != 0; }
  /// The prescribed displacement on the full dofs, Cartesian (zero at free and plainly clamped
  /// dofs): u_D.
  [[nodiscard]] Vector prescribed_values() const;
  /// Full displacement (num_dofs) from a free vector: the free values, and the prescribed values
  /// (u_D, zero for plain clamps) at the clamped dofs.
  [[nodiscard]] Vector expand(const Vector& free_values) const;
  /// Likewise with a factor per full dof (in the node's axes, as value(); a step of a loading
  /// history, Model::full_displacement): its prescribed value times scales(dof).
  [[nodiscard]] Vector expand(const Vector& free_values, const Vector& scales) const;
  /// Likewise from the values of some free dofs only, free dof f's at values(place(f)) (a rank's
  /// part of a distributed run: ContactProblem::solution_index); InputError where a free dof of
  /// this numbering has no place (-1).
  [[nodiscard]] Vector expand(const Vector& values, const Vector& scales,
                              const std::function<Index(Index)>& place) const;
  /// The prescribed displacement times a factor per full dof, Cartesian.
  [[nodiscard]] Vector prescribed_values(const Vector& scales) const;
  /// Free vector from a full (Cartesian) vector: at a node with a frame, its components along
  /// the frame's axes.
  [[nodiscard]] Vector restrict_to_free(const Vector& full_values) const;

 private:
  Index num_nodes_;
  int dim_;
  Index num_free_ = 0;
  bool finalized_ = false;
  std::vector<Index> free_;    // per full dof: free number, or -1 (clamped)
  std::vector<Index> place_;   // per node: its place in the node order; empty: the node
  Vector values_;              // per full dof: the prescribed value; empty while all are 0
  std::vector<int> frame_of_;  // per node: index into frames_, or -1; empty: none
  std::vector<Eigen::Matrix2d> frames_;  // local axes as columns
  // Full vector in place: each framed node's components from Cartesian to local (Q^T v) or
  // back (Q v).
  void rotate_frames(Vector& full, bool to_local) const;
};

}  // namespace signorini
