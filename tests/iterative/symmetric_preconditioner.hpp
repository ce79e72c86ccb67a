#pragma once
// A check shared by the multigrid tests: a preconditioner that CG can use is symmetric and
// positive definite, (M x, y) = (x, M y) and (M x, x) > 0, here on two fixed smooth vectors.

#include <gtest/gtest.h>

#include <cmath>

#include "signorini/backend/backend.hpp"
#include "signorini/iterative/linear_operator.hpp"

namespace signorini::testing {

inline void expect_symmetric_positive(Backend& be, Preconditioner& M, Index n) {
  const Vector x = Vector::LinSpaced(n, 0.0, 1.0).array().sin();
  const Vector y = Vector::LinSpaced(n, -2.0, 3.0).array().cos();
  DeviceVector mx(be, n), my(be, n);
  M.apply(to_device(be, x), mx);
  M.apply(to_device(be, y), my);
  const double xMy = x.dot(to_host(my)), yMx = y.dot(to_host(mx));
  EXPECT_NEAR(xMy, yMx, 1e-10 * std::abs(xMy));
  EXPECT_GT(x.dot(to_host(mx)), 0.0);
  EXPECT_GT(y.dot(to_host(my)), 0.0);
}

}  // namespace signorini::testing
