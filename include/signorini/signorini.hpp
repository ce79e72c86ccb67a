#pragma once
// The public API of the signorini library in one include: problem description, model building,
// the contact solvers with their options and summary, and the result writers.
//
//   #include <signorini/signorini.hpp>
//
// examples/cpp/ shows a complete program built against the installed package
// (find_package(signorini) and the target signorini::signorini).

#include "signorini/config.hpp"
#include "signorini/contact/contact_law.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/core/error.hpp"
#include "signorini/input/problem_file.hpp"
#include "signorini/interface/contact_boundary.hpp"
#include "signorini/interface/obstacle_parameters.hpp"
#include "signorini/mesh/box_mesh.hpp"
#include "signorini/mesh/gmsh_reader.hpp"
#include "signorini/mesh/mesh.hpp"
#include "signorini/mesh/mesh_arrays.hpp"
#include "signorini/mesh/mesh_description.hpp"
#include "signorini/mesh/node_cells.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/output/contact_csv.hpp"
#include "signorini/output/result_writer.hpp"
#include "signorini/output/solution_vtu.hpp"
#include "signorini/output/summary_json.hpp"
#include "signorini/problem/contact_node_values.hpp"
#include "signorini/problem/load_stepping.hpp"
#include "signorini/problem/model.hpp"
#include "signorini/problem/problem_spec.hpp"
#include "signorini/problem/resultants.hpp"
#include "signorini/problem/solver_plan.hpp"
#include "signorini/problem/unit_system.hpp"
