#include "signorini/problem/problem_spec.hpp"

namespace signorini {

ProblemSpec paper_benchmark(Index nx, Index ny) {
  ProblemSpec p;
  p.name = "paper";
  p.mesh = {0.0, 0.0, 3.0, 1.0, nx, ny};
  p.elasticity.material = {21.19e4, 0.277};
  p.elasticity.plane_model = PlaneModel::PlaneStrain;
  p.clamps = {{"left", {true, true, true}}};
  p.tractions.push_back(
      {"right", [](const Point&) { return Eigen::Vector3d(0.0, 1.0, 0.0); }, "(0, 1)", {}});
  p.tractions.push_back(
      {"top",
       [](const Point& x) { return Eigen::Vector3d(0.0, -2.0 / 3.0 * (3.0 - x(0)), 0.0); },
       "(0, -2/3 (3 - x))",
       {}});
  p.contacts.resize(1);
  p.contacts[0].boundary = "bottom";
  p.solver.r = 1e8;  // the paper's value (Section 5): Table 1's iteration counts need it
  return p;
}

}  // namespace signorini
