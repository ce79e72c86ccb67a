#pragma once
// One V-cycle of multigrid (geometric or smoothed-aggregation levels, multigrid_hierarchy.hpp) as
// the preconditioner of conjugate gradients for the
// generalised Hessian H = A + N^T diag(c) N (penalized_operator.hpp), docs/gpu.md.
//
// Levels come from the mesh (prolongations P_l from level l to level l-1, e.g. bilinear
// interpolation between nested rectangle meshes); the coarse operators are Galerkin products
// A_l = P_l^T A_{l-1} P_l and N_l = N_{l-1} P_l, formed once. Since P^T (N^T diag(c) N) P =
// N_l^T diag(c) N_l, a new active set only changes c: the hierarchy stays, and refresh() redoes
// the cheap parts (diagonals, eigenvalue estimates, the small coarsest factorisation). With
// smoothed aggregation's tentative prolongations at hand, refresh() also smooths each level's
// prolongation's rows at its active contact unknowns again with that level's H_l
// (contact_prolongation.hpp), and the coarse contact rows follow them: N_l = N P_H,0 P_H,1 ...
// (the coarse A_l stay). Each
// level's eigenvalue is A_l's, estimated once, or the contact zone's, estimated on the unknowns
// that the active rows touch (contact_zone_estimate.hpp), whichever is larger: no Lanczos steps
// on a whole level per active set (refresh()).
// Smoothing is Chebyshev–Jacobi; the coarsest level is solved by a dense Cholesky factorisation
// (on a GPU as its inverse, applied by one dense product on the device; on the CPU by the
// factor's triangular solves).

#include <Eigen/Cholesky>
#include <memory>
#include <vector>

#include "signorini/core/timing_table.hpp"
#include "signorini/iterative/chebyshev_smoother.hpp"
#include "signorini/iterative/contact_prolongation.hpp"
#include "signorini/iterative/multigrid_hierarchy.hpp"

namespace signorini {

struct MultigridOptions {
  ChebyshevOptions smoother;
  /// The coarsest level is solved exactly (dense) up to this size; above it by a Chebyshev sweep
  /// of 10 times the smoother's degree (then the preconditioner is no longer mesh-independent).
  Index max_dense_coarse = kDenseCoarsestUnknowns;
  /// Levels below this many unknowns estimate their lambda_max on the host, from a copy of the
  /// level: on a GPU a Lanczos step costs some 60 us of launches and synchronisations whatever
  /// the size, on the host about 30 ns per unknown, so the host wins below a few thousand
  /// unknowns (an estimate, to be measured on a GPU). On the CPU backend it is the same
  /// computation. 0: never.
  Index host_estimate_below = 4000;
  /// lambda_max(D^-1 A_l) of level l (0: the fine one) without contact where already known
  /// (MultigridHierarchy::jacobi_radii): the first refresh then skips those levels' Lanczos
  /// steps (12 products with each). Missing or 0: estimated here.
  std::vector<double> lambda_max;
  /// Smoothed aggregation's tentative prolongations and their omegas
  /// (MultigridHierarchy::tentatives; [l] for prolongation l): with them, each refresh smooths
  /// each level's prolongation's rows at its active contact unknowns with that level's Newton
  /// matrix (contact_prolongation.hpp). Null, or a level without one: A's prolongation there.
  const std::vector<SparseMatrix>* tentatives = nullptr;
  std::vector<double> omegas;
};

class MultigridPreconditioner final : public Preconditioner {
 public:
  /// `fine` is H on the finest level (it must outlive this object); A and N are its host
  /// matrices, `prolongations[l]` maps level l+1 to level l. `coarse_operators[l]`, if given
  /// (non-empty), is the matrix of level l+1, already formed (smoothed aggregation forms them);
  /// otherwise the Galerkin products are formed here. A, the prolongations, the coarse
  /// operators and options.tentatives must outlive this object: on the CPU they are multiplied
  /// in place, not copied, and the tentatives are read at the first refresh with contact.
  MultigridPreconditioner(PenalizedOperator& fine, const SparseMatrix& A, const SparseMatrix& N,
                          const std::vector<SparseMatrix>& prolongations, MultigridOptions options,
                          const std::vector<SparseMatrix>& coarse_operators = {});
  ~MultigridPreconditioner() override;

  /// After fine.set_weights(c): carries c to every level and redoes diagonals, eigenvalue
  /// estimates (on the contact zones, once A_l's own are known) and the coarsest factorisation.
  void refresh() override;
  void apply(const DeviceVector& r, DeviceVector& z) override;

  /// Unknowns per level, finest first.
  [[nodiscard]] std::vector<Index> level_sizes() const;
  /// The parts of the construction, for the summary's timings (docs/output.md): "multigrid:
  /// coarse operators" (the Galerkin products A_l and N_l, on the host), "multigrid: level
  /// uploads" (P, P^T and each level's operator to the backend) and "multigrid: first refresh"
  /// (work vectors, smoothers, the set-up for c = 0).
  [[nodiscard]] const TimingTable& setup_timings() const { return setup_timings_; }
  /// The fine level's lambda_max(D^-1 H) as the smoother uses it: estimated for c = 0 (or
  /// given), for another c the larger of that and the contact zone's estimate (refresh()).
  [[nodiscard]] double fine_lambda_max() const { return lambda_max(0); }
  /// The same on level `level` (0: the finest); 0 on a coarsest level solved exactly.
  [[nodiscard]] double lambda_max(std::size_t level) const;
  /// The V-cycle as last recorded by apply() (null before the first apply() after a refresh()):
  /// on a GPU, is_graph() tells whether it replays as one CUDA graph.
  [[nodiscard]] const RecordedWork* recorded_cycle() const { return recorded_.get(); }
  /// P_H - P of the last refresh (contact_prolongation.hpp) for the prolongation to level
  /// `level` (0: the fine one) from the next: its change for the active set; no nonzeros
  /// without contact, or where it is off.
  [[nodiscard]] const SparseMatrix& prolongation_change(std::size_t level) const;
  /// The contact rows of level `level` as the V-cycle uses them (N P_H,0 P_H,1 ... on the
  /// coarse levels), on the host.
  [[nodiscard]] SparseMatrix contact_rows(std::size_t level) const;

 private:
  struct Level;
  void cycle(std::size_t l, const DeviceVector& b, DeviceVector& x);
  void factor_coarsest();
  void update_contact_prolongation(const Vector& c);
  void make_contact_prolongations();
  void coarse_solve(const DeviceVector& b, DeviceVector& x);

  Backend& backend_;
  MultigridOptions options_;
  std::unique_ptr<Backend> host_;  // for the host copies of small levels (before levels_: it
                                   // must outlive them)
  std::vector<std::unique_ptr<Level>> levels_;
  TimingTable setup_timings_;
  // Host copies of the coarsest level, for its factorisation: A_L, and N_L^T (a column per
  // contact row).
  SparseMatrix coarse_A_, coarse_Nt_;
  // The smoother's lambda_max(D^-1 H) of a level for the current weights where it needs no
  // Lanczos steps on the level (refresh()); 0 where it must be estimated.
  double lambda_max_without_lanczos(Level& level, bool without_contact);
  std::vector<std::vector<Index>> fine_row_columns_;  // the unknowns of each row of N
  // Block weights (friction in 3D): the most unknowns that one node's `block` rows of N touch
  // together, the bound of refresh(), computed once per block size.
  double block_unknowns_bound(Index block);
  Index block_bound_size_ = 0;
  double block_bound_ = 0.0;
  // Whether the levels' prolongations may be smoothed with H at their active contact unknowns
  // (each Level holds its ContactProlongation, made at the first refresh with contact), whether
  // they are made, and whether the levels now hold a change.
  bool contact_prolongation_ = false;
  bool contact_prolongations_made_ = false;
  bool prolongation_changed_ = false;
  // The coarsest level's solve: on a GPU its explicit inverse, applied by one dense product; on
  // the CPU its Cholesky factor, applied by two triangular solves (as fast for one vector, and
  // the inverse cost twice the factorisation again at every refresh).
  std::unique_ptr<DeviceDenseMatrix> coarse_inverse_;
  std::unique_ptr<Eigen::LLT<Matrix>> coarse_factor_;
  // The V-cycle as recorded work (a CUDA graph on a GPU) for the last (r, z) pair; dropped by
  // refresh(), which changes the smoothers' coefficients and the coarse inverse.
  std::unique_ptr<RecordedWork> recorded_;
  const DeviceVector* recorded_r_ = nullptr;
  const DeviceVector* recorded_z_ = nullptr;
  const double* recorded_r_data_ = nullptr;
  const double* recorded_z_data_ = nullptr;
};

}  // namespace signorini
