#pragma once
// From a ProblemSpec to the discrete contact problem (14): mesh, dof numbering, stiffness, loads
// and contact set, with the time each phase took, and what the resultants of a solution need
// (problem/resultants.hpp): the full load vector, the clamped dofs of each clamp, the material.

#include <memory>
#include <string>
#include <vector>

#include "signorini/contact/contact_problem.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/friction_law.hpp"
#include "signorini/core/timing_table.hpp"
#include "signorini/fem/dof_map.hpp"
#include "signorini/iterative/multigrid_hierarchy.hpp"
#include "signorini/mesh/mesh.hpp"
#include "signorini/problem/problem_spec.hpp"

namespace signorini {

/// The dofs that one [[clamp]] or [[displacement]] entry holds (full, node-major numbers), each
/// counted for the first entry that clamps it, so that the reactions of the entries add up to the
/// total.
struct ClampedPart {
  std::string boundary;
  std::vector<Index> dofs;
};

/// Where a point load landed: the node it acts at, and how far that is from where it was asked.
struct PlacedPointLoad {
  Point requested = Point::Zero();
  Index node = 0;
  Point at = Point::Zero();
  double distance = 0.0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
};

/// A load or prescribed-displacement entry with load factors of its own in a loading history
/// (an entry's `factors`, problem-format.md [loading]); the others follow the history's factor.
struct LoadGroup {
  std::string entry;                   ///< "traction[1]", for messages
  std::vector<double> factors;         ///< one per step of the history
  Vector loads;                        ///< full: the entry's loads at factor 1 (empty: none)
  std::vector<Index> prescribed_dofs;  ///< full dofs whose prescribed value is the entry's
  Vector b;                            ///< free: its part of problem.b at factor 1
};

/// What a rank's part of the mesh lacks and its results need (docs/distributed.md, "The mesh in
/// parts"): rank 0 measures it on the whole mesh and sends it to every rank.
struct WholeMesh {
  Index nodes = 0;           ///< the whole mesh's nodes
  Eigen::VectorXd centroid;  ///< the mean of its nodes (the resultants' reference point)
  double radius = 0.0;       ///< the largest distance of a node from the centroid
  /// Per contact-set row (dim x contact size): the coordinates of its node, and the prescribed
  /// displacement there (DofMap::prescribed_at, at factor 1).
  Eigen::MatrixXd contact_points, contact_prescribed;
};

struct Model {
  Mesh mesh;
  DofMap dofs;
  ContactProblem problem;
  /// The levels of the multigrid preconditioner, made from the mesh (and A) when the solver
  /// options ask for multigrid; empty otherwise. A set-up argument of the solver
  /// (solve_contact(model.problem, options, &model.multigrid)), not part of the problem.
  MultigridHierarchy multigrid;
  /// The solver options to solve with: the spec's, with the path chosen from the problem's size
  /// when spec.solver.automatic_path is set (solver_plan.hpp), and why.
  ContactSolverOptions solver;
  std::string solver_reason;
  TimingTable timings;  ///< "mesh", "assembly", "loads", "contact set", "multigrid hierarchy"
  ElasticityOptions elasticity;
  /// Every applied load (tractions, body force, point loads) on the full dofs; problem.b is its
  /// free part.
  Vector loads;
  std::vector<ClampedPart> clamped_parts;
  std::vector<PlacedPointLoad> point_loads;
  /// The names of the contact boundary parts (contact.csv's `boundary` column), in the order of
  /// the contact set's rows: part i has rows contact_starts[i] to contact_starts[i + 1] - 1.
  std::vector<std::string> contact_boundaries;
  std::vector<Index> contact_starts;
  /// The entries with load factors of their own (empty without).
  std::vector<LoadGroup> load_groups;
  /// What prescribed displacements take off the contact gaps (contact_gaps): per contact row j
  /// and component k of its node, nu_j . (the component's axis) times the prescribed value;
  /// dim x contact size, empty when nothing is prescribed. The load group of each (column-major
  /// like the matrix; -1: the history's factor).
  Eigen::MatrixXd contact_gap_shift;
  std::vector<int> contact_gap_shift_group;
  /// On every rank of a distributed run on more than one rank (docs/distributed.md, "The mesh
  /// in parts"), `mesh` and `dofs` are the rank's part: node i of `mesh` is node
  /// global_nodes[i] of the whole mesh (increasing), and the dofs keep the whole problem's free
  /// numbers. `loads`, `clamped_parts` and the load groups' loads and prescribed dofs are then
  /// the part's (its nodes' full dofs), b and the groups' b the rank's rows; problem.contact
  /// (whole on every rank) names the whole mesh's nodes; `point_loads` are rank 0's alone where
  /// rank 0 built the whole model, every rank's where the model is made in parts.
  /// Empty: the mesh is whole.
  std::vector<Index> global_nodes;
  /// On a part: the whole mesh's facts that the results need. Empty where the mesh is whole.
  WholeMesh whole = {};
  /// On a part made by its rank (a box made in parts, docs/distributed.md): per node of `mesh`,
  /// the rank that accounts for it. Empty: by its free dofs (node_rank).
  std::vector<int> node_ranks = {};

  /// Whether `mesh` is a part of the whole (a rank's, global_nodes).
  [[nodiscard]] bool is_part() const { return !global_nodes.empty(); }
  /// The node of `mesh` that is node `node` of the whole mesh; -1 where the part lacks it.
  [[nodiscard]] Index local_node(Index node) const;
  /// The dofs of the whole mesh (a part's mesh has fewer).
  [[nodiscard]] Index num_dofs() const {
    return is_part() ? whole.nodes * mesh.dim() : dofs.num_dofs();
  }
  /// The rank that accounts for node `node` of `mesh` in sums over the whole mesh (the
  /// resultants, the contact nodes' displacements): node_ranks's where given, else the owner of
  /// its first free dof, rank 0 for a node without one; 0 unless the problem is partitioned.
  [[nodiscard]] int node_rank(Index node) const;
  /// The rank that accounts for cell `cell` (its piece of solution.pvtu, its internal forces):
  /// that of its first node where node_ranks are given (that rank's part has the cell, which
  /// touches its node), else that of its first node with a free dof, rank 0 for a cell without
  /// one.
  [[nodiscard]] int cell_rank(Index cell) const;
  /// The same for the ranks' ranges of the free dofs `starts` (a whole problem that each rank
  /// takes its rows of: parallel/row_partition.hpp partition_of).
  [[nodiscard]] int node_rank(Index node, const std::vector<Index>& starts) const;
  [[nodiscard]] int cell_rank(Index cell, const std::vector<Index>& starts) const;

  /// The name of the contact boundary of contact-set row j.
  [[nodiscard]] const std::string& contact_boundary_of(Index j) const;

  // A state of a loading history: `factor` on the loads and prescribed displacements without
  // factors of their own, each load group's at step `step` (from 1; 0: outside a history, the
  // groups at `factor` too). problem.b, loads and the contact gaps are those at factor 1.
  /// Per full dof, the factor of its prescribed value.
  [[nodiscard]] Vector prescribed_scales(double factor, int step) const;
  /// The applied loads on the full dofs.
  [[nodiscard]] Vector applied_loads(double factor, int step) const;
  /// The loads on the free dofs, b = f - K u_D.
  [[nodiscard]] Vector free_loads(double factor, int step) const;
  /// The contact set's gaps: g - nu . u_D at the node (interface/contact_boundary.cpp) with u_D
  /// scaled.
  [[nodiscard]] Vector contact_gaps(double factor, int step) const;
  /// The full displacement of a solution u (free dofs), with the prescribed values scaled.
  [[nodiscard]] Vector full_displacement(const Vector& u, double factor, int step) const;
  [[nodiscard]] Vector full_displacement(const ContactResult& r) const {
    return full_displacement(r.u, r.load_factor, r.load_step);
  }
};

/// Throws InputError on anything unusable: unknown boundary names, rigid motions that the clamps
/// leave free (named), bad material, non-finite loads or gaps, an empty contact boundary, a
/// traction on the contact boundary. `engine`: the distributed engine of the program's ranks
/// (docs/distributed.md; null in a serial program), which every rank passes alike; the model's
/// problem keeps it (ContactProblem::engine), for its solver and its result files.
Model build_model(const ProblemSpec& spec, DistributedEngine* engine = nullptr);

/// Builds the dof numbering for a mesh, clamps and prescribed displacements (exposed for tests
/// and other drivers). Clamps win over displacements at a dof both hold; among the displacements
/// the first entry wins. The free dofs are numbered node by node in `node_order` (empty: the
/// mesh's; build_model numbers the nodes of a Gmsh mesh in Z-order, fem/node_ordering.hpp).
DofMap make_dof_map(const Mesh& mesh, const std::vector<ClampSpec>& clamps,
                    const std::vector<DisplacementSpec>& displacements = {},
                    const std::vector<Index>& node_order = {});

/// Throws InputError naming the rigid motions that the clamps leave free (fem/free_rigid_motions).
void require_no_free_rigid_motion(const Mesh& mesh, const DofMap& dofs);

/// Warnings about a Gmsh mesh that only its cells can tell, once it is read (the problem file's
/// reader warns about the other meshes, whose cells it knows): a nearly incompressible material
/// (nu >= 0.45) on first-order cells, which lock. Each names the file, the mesh's linear cell
/// types and what to do (second-order cells: Mesh.ElementOrder = 2 in the .geo). Empty for
/// other mesh types, or where every cell is of the second order.
[[nodiscard]] std::vector<std::string> mesh_warnings(const ProblemSpec& spec, const Mesh& mesh);

}  // namespace signorini
