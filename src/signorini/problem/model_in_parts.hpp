#pragma once
// A model made in parts (docs/distributed.md, "A model made in parts"): each rank builds its
// own part of the model from its part of the mesh and the numbering of that part's nodes, and no
// rank holds the whole model. Two ways lead here: a generated box, whose ranks make their blocks
// and number them themselves (problem/box_model_in_parts.hpp), and a mesh from a file, which
// rank 0 reads, partitions and sends in parts of the mesh (problem/distributed_model.hpp). From
// the part on, both are the same: each rank assembles its loads, its rows of b and its columns
// of A, and its contact rows, which the ranks gather into the serial order, so that every rank
// holds the whole contact set.

#include <map>
#include <string>
#include <vector>

#include "signorini/contact/distributed_engine.hpp"
#include "signorini/core/error.hpp"
#include "signorini/parallel/byte_message.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {

/// A rank's part of the mesh and its numbering: what the rank builds its model from.
struct OwnPart {
  /// The cells of two layers around the rank's nodes (problem/model_part.hpp), in the whole
  /// mesh's order, with every boundary part of the whole mesh cut to them (empty where none
  /// lies in the part).
  Mesh mesh;
  /// Node i of the part is node global_nodes[i] of the whole mesh (increasing).
  std::vector<Index> global_nodes;
  /// The rank that owns each node of the part (Model::node_ranks).
  std::vector<int> node_ranks;
  /// For each boundary part, the place of each of its facets among the whole mesh's facets of
  /// that part: the contact rows' serial order follows it.
  std::map<std::string, std::vector<Index>> facet_keys;
  /// The part's nodes numbered as in the whole problem: their free numbers and prescribed
  /// values (kept exactly where the whole problem has a nonzero one: has_prescribed_values is
  /// the whole's), and for each full dof the entry that holds it (number_dofs; -1: free).
  DofMap dofs;
  std::vector<int> entry;
  /// Where each rank's unknowns begin, and the node (whole mesh) of each of this rank's.
  std::vector<Index> row_starts;
  std::vector<Index> node_of_unknown;
  /// In 2D, for each contact side, its nodes in the part with their places in the whole side's
  /// order (which walks the side's edges from its start: only the whole side knows it). A side
  /// without them is ordered by where its facets first name its nodes, as in 3D.
  std::map<std::string, std::vector<std::pair<Index, Index>>> node_keys = {};
};

/// Whether the problem's conditions can be made in parts (solver.partition = "auto", and what
/// the parts support so far: no normal displacement, whose local axes they lack). With
/// `numbered_whole` false (a box whose ranks number their own parts) no pinned clamp (`at`)
/// either: its node is the whole mesh's nearest. The others are built whole by rank 0 and sent
/// in parts of the model (problem/distributed_model.hpp).
[[nodiscard]] bool model_parts_support(const ProblemSpec& spec, bool numbered_whole);

/// Bad input found by some rank: every rank throws the lowest such rank's message, so that all
/// stop alike (a collective call). An empty message: this rank found none.
void agree_on_input(const DistributedEngine& engine, const std::string& message);

/// Runs f on this rank, then agrees with the others on whether the input was good (an
/// InputError thrown by f on any rank is thrown on every rank).
template <class F>
void on_every_rank(const DistributedEngine& engine, const F& f) {
  std::string error;
  try {
    f();
  } catch (const InputError& e) {
    error = e.what();
    if (error.empty()) error = "bad input";
  }
  agree_on_input(engine, error);
}

/// One value per rank, on every rank (for Index and double).
template <typename T>
[[nodiscard]] std::vector<T> values_of_ranks(const DistributedEngine& engine, T value);

/// This rank's model from its part (a collective call): its loads (the tractions, pressures and
/// body force on its part, exact at its nodes, whose cells and facets are all in the part; each
/// point load at the whole mesh's nearest node; the load groups of the entries with load factors
/// of their own), rows of b and columns of A, rigid-body modes, the whole contact set, the whole
/// mesh's facts and the plan. Bad input found by any rank is thrown as InputError on every
/// rank. `timings` so far go on.
[[nodiscard]] Model model_from_own_part(const ProblemSpec& spec, OwnPart part,
                                        DistributedEngine& engine, TimingTable timings);

}  // namespace signorini
