#pragma once
// Internal to linalg: CHOLMOD's 64-bit interface, a copy of the upper triangle of an Eigen matrix
// in CHOLMOD's own storage, and status checks that turn CHOLMOD failures into exceptions.

#include <cholmod.h>

#include <cstdint>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "signorini/core/error.hpp"
#include "signorini/core/types.hpp"
#include "signorini/linalg/detail/huge_page_memory.hpp"

namespace signorini::detail {

using CholmodInt = SuiteSparse_long;

/// CHOLMOD's workspace and settings, started and finished with the object. CHOLMOD prints
/// nothing: its failures come back as exceptions through check_cholmod().
///
/// Supernodes are amalgamated more than CHOLMOD's defaults (nrelax = 4, 16, 48): two adjacent
/// supernodes of the elimination tree merge when the merged one has at most 16 columns, or at
/// most 64 and 10 % explicit zeros, or at most 256 and 5 % (zrelax unchanged). Fewer, larger
/// dense blocks for the BLAS: on the paper's problem the condensation factorises in 0.29-0.34 s
/// instead of 0.44-0.56 s at 480x160 and in 1.6-2.0 s instead of 2.7-3.8 s at 960x320, for
/// 20 % more memory in the factor (docs/performance.md). The factor holds the same matrix;
/// only the rounding differs.
struct CholmodCommon {
  cholmod_common common{};
  CholmodCommon() {
    use_huge_pages_for_cholmod();  // before CHOLMOD's first allocation (huge_page_memory.hpp)
    cholmod_l_start(&common);
    common.print = 0;
    common.error_handler = nullptr;
    common.nrelax[0] = 16;
    common.nrelax[1] = 64;
    common.nrelax[2] = 256;
  }
  ~CholmodCommon() { cholmod_l_finish(&common); }
  CholmodCommon(const CholmodCommon&) = delete;
  CholmodCommon& operator=(const CholmodCommon&) = delete;
};

/// Runs CHOLMOD's numeric factorisation on the calling thread alone. Debian's CHOLMOD 3 is built
/// with CHOLMOD_OMP_NUM_THREADS = 4 and asks for four OpenMP threads in its supernodal assembly
/// loops whatever the machine has (num_threads(4) overrides OMP_NUM_THREADS). Those loops are
/// short scatters, not flops (the flops are BLAS calls), and the team costs more than it saves:
/// on the 2-core development machine the paper's problem at 480x160 factorised in 0.70-0.90 s
/// with the four threads and 0.42-0.50 s without, and at 960x320 in 4.3-4.7 s against 2.4-2.6 s
/// (docs/performance.md). max-active-levels 0 makes every parallel region inactive; the previous
/// value comes back when the scope ends. The ICV is process-wide: a program that runs its own
/// OpenMP regions on other threads during a factorisation gets them serial for that time.
class SerialOpenMpScope {
 public:
#ifdef _OPENMP
  SerialOpenMpScope() : saved_(omp_get_max_active_levels()) { omp_set_max_active_levels(0); }
  ~SerialOpenMpScope() { omp_set_max_active_levels(saved_); }
#else
  SerialOpenMpScope() = default;  // without OpenMP here, CHOLMOD keeps its own thread count
#endif
  SerialOpenMpScope(const SerialOpenMpScope&) = delete;
  SerialOpenMpScope& operator=(const SerialOpenMpScope&) = delete;

 private:
#ifdef _OPENMP
  int saved_;
#endif
};

/// Throws NumericalError if the last CHOLMOD call failed.
inline void check_cholmod(const cholmod_common& c, const char* what) {
  if (c.status == CHOLMOD_NOT_POSDEF)
    throw NumericalError(std::string("CHOLMOD ") + what +
                         ": matrix is not positive definite (is the body held by clamped "
                         "boundaries?)");
  if (c.status == CHOLMOD_OUT_OF_MEMORY)
    throw NumericalError(std::string("CHOLMOD ") + what + ": out of memory");
  if (c.status < CHOLMOD_OK)
    throw NumericalError(std::string("CHOLMOD ") + what + " failed with status " +
                         std::to_string(c.status));
}

/// The upper triangle of a symmetric matrix (stype = 1) in CHOLMOD storage, with the positions
/// of its values in the Eigen matrix so that new values of the same pattern are copied cheaply.
struct CholmodUpper {
  cholmod_sparse* matrix = nullptr;
  std::vector<CholmodInt> value_map;  // entry k of `matrix` is A.valuePtr()[value_map[k]]
  Index full_nnz = 0;
  std::uint64_t pattern_hash = 0;  // of A's full pattern (pattern_hash()), checked before a copy

  /// Copies the values of A (same pattern as at construction) into `matrix`.
  void copy_values(const SparseMatrix& A) const {
    auto* vals = static_cast<double*>(matrix->x);
    const double* av = A.valuePtr();
    for (std::size_t k = 0; k < value_map.size(); ++k) vals[k] = av[value_map[k]];
  }
};

/// A 64-bit FNV-1a hash of the pattern of A (sizes, column starts, row indices): two patterns
/// with the same count but entries elsewhere differ in it (with overwhelming probability).
inline std::uint64_t pattern_hash(const SparseMatrix& A) {
  std::uint64_t h = 14695981039346656037ULL;
  auto mix = [&h](std::uint64_t v) {
    h ^= v;
    h *= 1099511628211ULL;
  };
  mix(static_cast<std::uint64_t>(A.rows()));
  mix(static_cast<std::uint64_t>(A.cols()));
  for (Index j = 0; j <= A.cols(); ++j) mix(static_cast<std::uint64_t>(A.outerIndexPtr()[j]));
  for (Index k = 0; k < A.nonZeros(); ++k) mix(static_cast<std::uint64_t>(A.innerIndexPtr()[k]));
  return h;
}

/// Owns a cholmod_dense that CHOLMOD allocated (a solve's result): freed on every path, also when
/// a later CHOLMOD call throws.
class OwnedDense {
 public:
  OwnedDense(cholmod_dense* d, cholmod_common& common) : d_(d), common_(&common) {}
  ~OwnedDense() { cholmod_l_free_dense(&d_, common_); }
  OwnedDense(const OwnedDense&) = delete;
  OwnedDense& operator=(const OwnedDense&) = delete;
  [[nodiscard]] cholmod_dense* get() const { return d_; }
  [[nodiscard]] const double* values() const { return static_cast<const double*>(d_->x); }

 private:
  cholmod_dense* d_;
  cholmod_common* common_;
};

/// Allocates the upper triangle of A (values copied too). Free with cholmod_l_free_sparse.
/// `keep_value_map`: remember where the values came from, for copy_values() later.
inline CholmodUpper make_cholmod_upper(const SparseMatrix& A, cholmod_common& common,
                                       bool keep_value_map = true) {
  if (A.rows() != A.cols()) throw NumericalError("CHOLMOD: matrix is not square");
  const Index n = A.rows();
  CholmodUpper out;
  out.full_nnz = A.nonZeros();
  if (keep_value_map) out.pattern_hash = pattern_hash(A);
  out.value_map.reserve(static_cast<std::size_t>(A.nonZeros() / 2 + n));
  std::vector<CholmodInt> colptr(static_cast<std::size_t>(n + 1), 0);
  for (Index j = 0; j < n; ++j) {
    for (int k = A.outerIndexPtr()[j]; k < A.outerIndexPtr()[j + 1]; ++k)
      if (A.innerIndexPtr()[k] <= j) out.value_map.push_back(k);
    colptr[static_cast<std::size_t>(j + 1)] = static_cast<CholmodInt>(out.value_map.size());
  }
  out.matrix = cholmod_l_allocate_sparse(static_cast<std::size_t>(n), static_cast<std::size_t>(n),
                                         out.value_map.size(), /*sorted=*/1, /*packed=*/1,
                                         /*stype=*/1, CHOLMOD_REAL, &common);
  check_cholmod(common, "allocate");
  std::copy(colptr.begin(), colptr.end(), static_cast<CholmodInt*>(out.matrix->p));
  auto* ri = static_cast<CholmodInt*>(out.matrix->i);
  for (Index j = 0; j < n; ++j)
    for (int k = A.outerIndexPtr()[j]; k < A.outerIndexPtr()[j + 1]; ++k)
      if (A.innerIndexPtr()[k] <= j) *ri++ = A.innerIndexPtr()[k];
  out.copy_values(A);
  if (!keep_value_map) out.value_map = {};
  return out;
}

/// A read-only dense view of a vector for CHOLMOD (CHOLMOD does not write to its inputs).
inline cholmod_dense dense_view(const Vector& v) {
  cholmod_dense d{};
  d.nrow = static_cast<std::size_t>(v.size());
  d.ncol = 1;
  d.nzmax = d.nrow;
  d.d = d.nrow;
  d.x = const_cast<double*>(v.data());
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

}  // namespace signorini::detail
