#pragma once
// Smoothed-aggregation levels made by signorini itself on the distributed path
// (solver.petsc_multigrid = "aggregation"; docs/distributed.md, "Our own levels"): the serial
// tool's coarsening (iterative/smoothed_aggregation.hpp) on each rank's own nodes, with the
// prolongation smoothed and the Galerkin products formed by the serial kernels on the rank's
// threads, and PETSc carrying what crosses the ranks.
//
// Per level, on each rank:
//  - its rows of A_l as the columns of its own unknowns (n_ext x n_own: its own unknowns first,
//    then the others' that its rows touch, the ghosts), read in place from PETSc's CSR arrays
//    on one rank, copied from its diagonal and off-diagonal blocks on several;
//  - its nodes aggregated among themselves ("uncoupled" aggregation: no aggregate crosses two
//    ranks, so no rank waits for another's choices), the tentative prolongation T of its rows
//    and the coarse near-null space, as the serial aggregate_level does;
//  - T's rows of the ghosts fetched from their ranks (MatCreateSubMatrices), the rank's rows of
//    P = (I - omega D^-1 A_l) T formed (omega = 4 / (3 rho(D^-1 A_l)), Vanek, Mandel and
//    Brezina's eq. 4.4), then P's rows of the ghosts fetched likewise;
//  - the rank's share of P^T A_l P (galerkin_product.hpp: the products of its own rows of A_l)
//    added into A_{l+1} by PETSc's COO assembly, which sends the entries of the other ranks'
//    rows to them.
// On one rank this is the serial hierarchy (the same aggregates, prolongations and products).
// The coarsening stops as the serial one does: a level of at most 1,000 unknowns (over all
// ranks; the fine level is coarsened once however small, since PCMG solves its coarsest level
// directly), or one that coarsens by less than a fifth.

#include <petscmat.h>

#include <vector>

namespace signorini::petsc {

/// The levels below the fine one, fine first: prolongations[l] takes level l + 1 to level l
/// (level 0 the fine one), operators[l] is level l + 1's Galerkin product; the caller owns the
/// matrices. jacobi_radii[l]: lambda_max(D^-1 A_l) of level l (0: the fine one) where the maker
/// estimated it (missing where not). Made here, or by GAMG (petsc_contact_multigrid.cpp).
struct CoarseLevels {
  std::vector<Mat> prolongations;
  /// restrictions[l] = prolongations[l]^T where the maker has it (else null, or none at all).
  std::vector<Mat> restrictions;
  std::vector<Mat> operators;
  std::vector<double> jacobi_radii;
};

class LevelContactProlongations;

/// The levels of A (AIJ, symmetric positive definite, its block size the unknowns of a node and
/// its near-null space attached, as for GAMG; without one, the translations of the nodes'
/// unknowns). With `contact`, each level's rows that its contact prolongation needs are given
/// to it, finest first, while it takes them (level_contact_prolongation.hpp). Collective on A's
/// communicator.
[[nodiscard]] CoarseLevels aggregation_levels(Mat A, LevelContactProlongations* contact = nullptr);

}  // namespace signorini::petsc
