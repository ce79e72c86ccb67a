#include "signorini/iterative/contact_zone_estimate.hpp"

#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "signorini/backend/host_backend.hpp"
#include "signorini/core/error.hpp"
#include "signorini/iterative/eigenvalue_estimate.hpp"
#include "signorini/iterative/jacobi_preconditioner.hpp"

namespace signorini {

namespace {

// Rows in compressed form on the zone's own numbering.
struct ZoneRows {
  std::vector<Index> start{0}, column;
  std::vector<double> value;
  [[nodiscard]] Index rows() const { return static_cast<Index>(start.size()) - 1; }
  void end_row() { start.push_back(static_cast<Index>(column.size())); }
};

// y = A_ZZ x + B^T (B x), B = diag(c)^1/2 N_JZ: H_ZZ on host vectors.
class ZoneOperator final : public LinearOperator {
 public:
  ZoneOperator(ZoneRows a, ZoneRows b) : a_(std::move(a)), b_(std::move(b)) {}
  [[nodiscard]] Index size() const override { return a_.rows(); }
  void apply(const DeviceVector& x, DeviceVector& y) override {
    const double* xs = x.data();
    double* ys = y.data();
    for (Index i = 0; i < a_.rows(); ++i) {
      double sum = 0.0;
      for (Index p = a_.start[us(i)]; p < a_.start[us(i) + 1]; ++p)
        sum += a_.value[us(p)] * xs[a_.column[us(p)]];
      ys[i] = sum;
    }
    for (Index j = 0; j < b_.rows(); ++j) {
      double bx = 0.0;
      for (Index p = b_.start[us(j)]; p < b_.start[us(j) + 1]; ++p)
        bx += b_.value[us(p)] * xs[b_.column[us(p)]];
      for (Index p = b_.start[us(j)]; p < b_.start[us(j) + 1]; ++p)
        ys[b_.column[us(p)]] += b_.value[us(p)] * bx;
    }
  }

 private:
  static std::size_t us(Index i) { return static_cast<std::size_t>(i); }
  ZoneRows a_, b_;
};

}  // namespace

double contact_zone_lambda_max(const SparseMatrix& A, const SparseMatrix& Nt, const Vector& c,
                               int steps) {
  if (A.rows() != A.cols() || Nt.rows() != A.rows() || c.size() != Nt.cols())
    throw NumericalError(
        fmt::format("contact zone estimate: A is {} x {}, N^T {} x {}, and {} weights", A.rows(),
                    A.cols(), Nt.rows(), Nt.cols(), c.size()));
  // Z in the order the active rows reach it, and B's rows on Z's numbering.
  std::vector<Index> local(static_cast<std::size_t>(A.rows()), -1), zone;
  ZoneRows b;
  for (Index j = 0; j < Nt.outerSize(); ++j) {
    if (!(c(j) > 0.0)) continue;
    const double root = std::sqrt(c(j));
    for (SparseMatrix::InnerIterator it(Nt, j); it; ++it) {
      if (it.value() == 0.0) continue;
      Index& z = local[static_cast<std::size_t>(it.row())];
      if (z < 0) {
        z = static_cast<Index>(zone.size());
        zone.push_back(it.row());
      }
      b.column.push_back(z);
      b.value.push_back(root * it.value());
    }
    b.end_row();
  }
  const auto n = static_cast<Index>(zone.size());
  if (n == 0) return 0.0;
  // A_ZZ by rows (A is symmetric: its column i is its row i), and D_ZZ = diag(A_ZZ) + diag(B^T B).
  ZoneRows a;
  Vector d = Vector::Zero(n);
  for (Index z = 0; z < n; ++z) {
    for (SparseMatrix::InnerIterator it(A, zone[static_cast<std::size_t>(z)]); it; ++it) {
      const Index w = local[static_cast<std::size_t>(it.row())];
      if (w < 0) continue;
      a.column.push_back(w);
      a.value.push_back(it.value());
      if (w == z) d(z) += it.value();
    }
    a.end_row();
  }
  for (std::size_t p = 0; p < b.column.size(); ++p) d(b.column[p]) += b.value[p] * b.value[p];
  if (!(d.array() > 0.0).all())
    throw NumericalError("contact zone estimate: a diagonal entry of H is not positive");
  ZoneOperator H(std::move(a), std::move(b));
  HostBackend host;
  const DeviceVector dinv = to_device(host, Vector(d.cwiseInverse()));
  DiagonalPreconditioner jacobi(dinv);
  const DeviceVector start = to_device(host, eigenvalue_estimate_start(n));
  return estimate_largest_eigenvalue(H, jacobi, start, steps);
}

}  // namespace signorini
