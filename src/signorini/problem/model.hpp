#pragma once
// From a ProblemSpec to the discrete contact problem (14): mesh, dof numbering, stiffness, loads
// and contact set, with the time each phase took.

#include "signorini/contact/contact_problem.hpp"
#include "signorini/core/timing_table.hpp"
#include "signorini/fem/dof_map.hpp"
#include "signorini/mesh/mesh.hpp"
#include "signorini/problem/problem_spec.hpp"

namespace signorini {

struct Model {
  Mesh mesh;
  DofMap dofs;
  ContactProblem problem;
  TimingTable timings;  ///< "mesh", "assembly", "loads", "contact set"
};

/// Throws InputError on anything unusable: unknown boundary names, no clamped dof, bad material,
/// non-finite loads or gaps, an empty contact boundary.
Model build_model(const ProblemSpec& spec);

/// Builds the dof numbering for a mesh and clamps (exposed for tests and other drivers).
DofMap make_dof_map(const Mesh& mesh, const std::vector<ClampSpec>& clamps);

}  // namespace signorini
