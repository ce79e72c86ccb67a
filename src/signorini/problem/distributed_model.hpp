#pragma once
// The model of a distributed run on more than one rank (docs/distributed.md, "The mesh in
// parts"). Rank 0 alone reads the mesh and builds the whole model as a serial run does, except
// the stiffness; it sends each other rank the node graph's rows to partition, then its part of
// the model (problem/model_part.hpp), then what every rank holds whole (the contact set, the
// partition, the whole mesh's facts). Every rank, rank 0 too, then builds its model from its
// part: the stiffness columns and rigid-body modes of its unknowns; rank 0 lets the whole go.
// A failure on rank 0 reaches the others as the one message that rank 0 reports.

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "signorini/contact/distributed_engine.hpp"
#include "signorini/parallel/node_partition.hpp"
#include "signorini/problem/model.hpp"
#include "signorini/problem/solver_plan.hpp"

namespace signorini {

/// Rank 0's side of the agreement: the others wait, at two points of the build, to learn
/// whether rank 0 went on or failed (and with what message).
class RootAnnouncements {
 public:
  explicit RootAnnouncements(const DistributedEngine& engine) : engine_(engine) {}
  /// Tells the others that rank 0 got this far.
  void ok();
  /// From here the others wait for the next ok() (or failed()).
  void owe() { owed_ = true; }
  /// Tells the others, if they wait, that rank 0 failed with this message.
  void failed(const std::string& message);

 private:
  const DistributedEngine& engine_;
  bool owed_ = true;
};

/// Rank 0: sends each other rank its rows of the node graph, made one rank at a time, and
/// returns its own (with the node of every vertex, for partition_order).
[[nodiscard]] NodeGraph send_node_graph_rows(const NodeGraphRows& rows,
                                             const DistributedEngine& engine);

/// Rank 0: sends each other rank its part of `model` (whole, partitioned), with its rows of the
/// whole b and of each load group's b, then broadcasts what every rank holds whole (kept in
/// `everyone`), the parameters of its friction law (`friction`, the model's problem's law; null
/// without friction) among them. Returns rank 0's own part, for model_from_part: it accounts for
/// the nodes without a free dof (Model::node_rank), so it has the cells around them too.
[[nodiscard]] std::vector<char> send_model_parts(const Model& model, const FrictionLaw* friction,
                                                 const Vector& whole_b,
                                                 const std::vector<Vector>& whole_group_b,
                                                 const ProblemSize& size,
                                                 const DistributedEngine& engine,
                                                 std::vector<char>& everyone);

/// Rank 0, where the conditions can be made in parts (model_in_parts.hpp): sends each other
/// rank its part of the mesh (two layers of cells around its nodes, with the boundary parts cut
/// to them and their facets' places) and that part's numbering, from the whole mesh and its
/// numbering after the partition (`owner`: number_dofs's entries; `problem`: the row starts and
/// the node of each unknown). A node without a free dof goes to the rank of a free node of one
/// of its cells (rank 0 where none has one). `contact_orders`: in 2D, each contact side's nodes
/// in the whole side's order (contact_orders). Returns rank 0's own part's bytes.
[[nodiscard]] std::vector<char> send_mesh_parts(
    const Mesh& mesh, const DofMap& dofs, const std::vector<int>& owner,
    const ContactProblem& problem, const std::map<std::string, std::vector<Index>>& contact_orders,
    const DistributedEngine& engine);

/// In 2D, the nodes of each contact side in the order of its contact rows (the walk along its
/// edges, interface/contact_boundary.hpp), by side; empty in 3D, where each part orders them
/// itself. InputError for a side that is not one.
[[nodiscard]] std::map<std::string, std::vector<Index>> contact_orders(const ProblemSpec& spec,
                                                                       const Mesh& mesh);

/// A rank's model from its part of the mesh (send_mesh_parts's bytes; a collective call, every
/// rank alike: model_in_parts.hpp).
[[nodiscard]] Model model_from_mesh_part(const ProblemSpec& spec, std::vector<char> bytes,
                                         DistributedEngine& engine, TimingTable timings);

/// Every other rank: its model, from what rank 0 sends (the same calls in the same order).
[[nodiscard]] Model receive_model_part(const ProblemSpec& spec, DistributedEngine& engine);

/// A rank's model from its part's bytes and those that every rank gets (send_model_parts): the
/// part of the mesh, its stiffness columns (assembled here) and rigid-body modes, the rank's
/// rows of b. `timings` so far go on.
[[nodiscard]] Model model_from_part(const ProblemSpec& spec, std::vector<char> part,
                                    std::vector<char> everyone, DistributedEngine& engine,
                                    TimingTable timings);

/// The solver plan of a model of this size (solver_plan.hpp) and, on the distributed path (on
/// `distributed`; null: serial), the reason that says so: rank 0's and every other rank's alike.
[[nodiscard]] SolverPlan plan_model_solver(const ProblemSpec& spec, const ProblemSize& size,
                                           const DistributedEngine* distributed);
/// Whether the plan's Newton systems are solved by CG with multigrid (the rigid-body modes then
/// go with the problem on the distributed path).
[[nodiscard]] bool uses_multigrid(const ContactSolverOptions& options);
/// The load group (index into `groups`) of each of `num_dofs` dofs whose prescribed value has
/// factors of its own, -1 elsewhere; empty when no group prescribes any.
[[nodiscard]] std::vector<int> load_group_of_dofs(const std::vector<LoadGroup>& groups,
                                                  Index num_dofs);

/// The material of each of the mesh's regions (`names`), from the spec's [[region]] entries;
/// InputError for a name that the mesh lacks.
[[nodiscard]] ElasticityOptions region_elasticity(const ProblemSpec& spec,
                                                  const std::vector<std::string>& names);

/// InputError where the spec's points and vectors imply another dimension than the mesh's.
void require_implied_dimension(const ProblemSpec& spec, int dim);
/// The dof numbering of a mesh (make_dof_map), and for each full dof the entry that holds it
/// (-1: free): clamp c as c, displacement entry i as clamps.size() + i.
[[nodiscard]] DofMap number_dofs(const Mesh& mesh, const std::vector<ClampSpec>& clamps,
                                 const std::vector<DisplacementSpec>& displacements,
                                 std::vector<int>& owner,
                                 const std::vector<Index>& node_order = {});
/// The dofs of each [[clamp]], then of each [[displacement]] entry, from number_dofs's owners.
[[nodiscard]] std::vector<ClampedPart> clamped_parts(
    const std::vector<ClampSpec>& clamps, const std::vector<DisplacementSpec>& displacements,
    const std::vector<int>& owner);
/// Adds the tractions, pressures and body force of `spec` on `mesh` to the full vector that
/// into(factors, entry) returns for each entry (its load factors and name, "traction[1]").
void add_surface_and_body_loads(
    const ProblemSpec& spec, const Mesh& mesh,
    const std::function<Vector&(const std::vector<double>&, std::string)>& into);

/// The friction law of the contact set, node by node from the sections' laws (Tresca's slip
/// bound at row j's point, `point(j)`), over the rows that `starts` divides among the sections
/// (Model::contact_starts); null when no boundary has friction. InputError for a slip bound that
/// is negative or not finite, and where the options' path with `engine` (null: none) does not
/// take the law (method_table.hpp: semismooth Newton with friction on the distributed path).
[[nodiscard]] std::shared_ptr<const FrictionLaw> contact_friction_law(
    const ProblemSpec& spec, int dim, const std::vector<Index>& starts,
    const std::function<Point(Index j)>& point, const DistributedEngine* engine);
/// The friction laws the contact sections state, in their order (empty: none): what names the
/// law (FrictionLaw::name) on every rank alike, wherever its parameters come from.
[[nodiscard]] std::vector<FrictionKind> friction_kinds(const ProblemSpec& spec);

/// f - K u_D, the loads of the free dofs as a full vector (docs/method.md: a nonzero prescribed
/// displacement u_D loads the free dofs; the full solution is u_D plus the free part), with u_D
/// = `u_d`, or the DofMap's prescribed values where `u_d` is empty; f itself where the DofMap
/// has none. On a part of the mesh it is exact at the nodes whose cells are all in the part.
[[nodiscard]] Vector free_loads(const Mesh& mesh, const DofMap& dofs,
                                const ElasticityOptions& elasticity, const Vector& f,
                                const Vector& u_d = {});

}  // namespace signorini
