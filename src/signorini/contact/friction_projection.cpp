#include "signorini/contact/friction_projection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace signorini {

namespace {

// The tangential part: z_t projected onto the ball of radius rho, with the derivative with
// respect to z_t written into D's tangential block. A zero radius gives a zero force (and
// derivative), a zero z_t inside a positive radius sticks.
void project_tangential(const Eigen::VectorXd& z, double rho, FrictionProjection& p) {
  const Eigen::Index d = z.size();
  const Eigen::VectorXd zt = z.tail(d - 1);
  const double norm = zt.norm();
  if (rho > 0.0 && norm < rho) {
    p.force.tail(d - 1) = zt;
    p.derivative.bottomRightCorner(d - 1, d - 1).setIdentity();
    return;
  }
  p.sliding = true;
  if (rho <= 0.0 || norm == 0.0) return;  // no tangential force
  const Eigen::VectorXd t = zt / norm;
  p.force.tail(d - 1) = rho * t;
  // d(rho z_t / |z_t|) / d z_t = (rho / |z_t|) (I - t t^T)
  p.derivative.bottomRightCorner(d - 1, d - 1) =
      (rho / norm) * (Eigen::MatrixXd::Identity(d - 1, d - 1) - t * t.transpose());
}

FrictionProjection start(const Eigen::VectorXd& z, double bound, const char* what) {
  if (z.size() < 2 || z.size() > 3)
    throw std::invalid_argument(
        "friction projection: z has a normal and 1 or 2 tangential "
        "components");
  if (!(bound >= 0.0) || !std::isfinite(bound))
    throw std::invalid_argument(std::string("friction projection: ") + what +
                                " must be finite and >= 0");
  FrictionProjection p;
  p.force = Eigen::VectorXd::Zero(z.size());
  p.derivative = Eigen::MatrixXd::Zero(z.size(), z.size());
  p.in_contact = z(0) > 0.0;
  if (p.in_contact) {
    p.force(0) = z(0);
    p.derivative(0, 0) = 1.0;
  }
  return p;
}

}  // namespace

FrictionProjection project_tresca(const Eigen::VectorXd& z, double slip_bound) {
  FrictionProjection p = start(z, slip_bound, "the slip bound");
  project_tangential(z, slip_bound, p);
  // psi = max(z_n, 0)^2 / 2 + (|z_t|^2 inside the ball, s (2 |z_t| - s) outside) / 2: the
  // outside's |z_t|^2 - (|z_t| - s)^2 without cancellation.
  const double zt = z.tail(z.size() - 1).norm();
  const double zn = std::max(z(0), 0.0);
  p.potential = 0.5 * zn * zn +
                (zt < slip_bound ? 0.5 * zt * zt : 0.5 * slip_bound * (2.0 * zt - slip_bound));
  return p;
}

FrictionProjection project_coulomb(const Eigen::VectorXd& z, double mu) {
  FrictionProjection p = start(z, mu, "the friction coefficient");
  p.potential = std::numeric_limits<double>::quiet_NaN();
  if (!p.in_contact) {
    p.sliding = false;  // separated: no force at all
    return p;
  }
  const double rho = mu * z(0);
  project_tangential(z, rho, p);
  if (p.sliding && rho > 0.0) {
    // The radius mu z_n moves with z_n: d(rho t) / d z_n = mu t.
    const Eigen::Index d = z.size();
    const Eigen::VectorXd t = z.tail(d - 1).normalized();
    p.derivative.bottomLeftCorner(d - 1, 1) = mu * t;
  }
  return p;
}

}  // namespace signorini
