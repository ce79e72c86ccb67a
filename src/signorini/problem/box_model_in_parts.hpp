#pragma once
// A box made in parts (docs/distributed.md, "A box made in parts"): on more than one rank a
// generated box needs no rank to hold the whole mesh or model. Each rank makes its block of the
// box's cubes with two layers around it (parallel/box_partition.hpp), numbers the dofs of the
// lattice points it owns, learns those of its other points from their owners, assembles its
// loads, its rows of b and of A and its contact rows, and the ranks gather the contact set,
// which every rank holds whole. The model is the one that a part sent by rank 0 gives
// (problem/distributed_model.hpp), up to the numbering of the unknowns (rank by rank, each
// rank's points in the box's order) and to rounding in the sums over the ranks.

#include "signorini/contact/distributed_engine.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {

/// Whether the problem can be made in parts on `ranks` ranks: a box (and solver.partition =
/// "auto"), with what the parts support (model_in_parts.hpp; no pinned clamp (`at`) here, whose
/// node is the whole box's nearest), and at least one cube per rank along each axis of some
/// grid of the ranks. The others are made by rank 0 and sent in parts.
[[nodiscard]] bool box_in_parts(const ProblemSpec& spec, int ranks);

/// This rank's model of a box made in parts (a collective call). Bad input found by any rank
/// is thrown as InputError on every rank, with the lowest such rank's message.
[[nodiscard]] Model build_box_model_in_parts(const ProblemSpec& spec, DistributedEngine& engine);

}  // namespace signorini
