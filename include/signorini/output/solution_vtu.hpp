#pragma once
// The ParaView files of a run (docs/output.md): solution.vtu, the whole mesh with the
// displacement, the stresses and the contact quantities as point data, and contact.vtu, the
// contact boundary Gamma_K alone as line cells.

#include <string>
#include <vector>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/problem/contact_node_values.hpp"
#include "signorini/problem/model.hpp"
#include "signorini/problem/problem_spec.hpp"

namespace signorini {

/// solution.vtu. Point data:
///   displacement      3 components (u_x, u_y, 0), m
///   stress            6 components XX, YY, ZZ, XY, YZ, XZ (ParaView's symmetric tensor order;
///                     YZ = XZ = 0), averaged at the nodes (fem/nodal_stress.hpp), MPa
///   von_mises         MPa
///   contact_pressure  l_j >= 0 on the contact boundary, MPa
///   gap               the initial gap g_j on the contact boundary, m
///   contact_active    1 where l_j > 0 (the body presses on the foundation)
///   contact_boundary  1 on the nodes of the contact boundary
/// The last four are 0 off the contact boundary (never NaN), which contact_boundary tells apart.
/// 2D only (throws InputError otherwise).
std::string solution_vtu(const ContactResult& result, const Model& model);

/// One piece of solution.vtu for a distributed run (docs/distributed.md): the given cells and the
/// nodes they use, with the same arrays; `pvtu`, when not null, receives the solution.pvtu that
/// names `pieces` (file names beside it).
std::string solution_vtu_piece(const ContactResult& result, const Model& model,
                               const std::vector<Index>& cells,
                               const std::vector<std::string>& pieces, std::string* pvtu);

/// contact.vtu: the contact nodes in the order of contact.csv, its facets as line cells, and the
/// point data displacement, normal (nu_j, 3 components), normal_displacement (u . nu),
/// tangential_displacement (u . tau, tau = (-nu_y, nu_x)), contact_pressure, gap, deformed_gap
/// (g - u . nu: 0 where the body touches, > 0 where it has lifted off) and contact_active.
/// On a rank's part of the mesh (Model::is_part) a collective call: contact_node_values.
std::string contact_vtu(const ContactResult& result, const Model& model);
/// The same from the contact nodes' values made once (contact_node_values).
std::string contact_vtu(const ContactResult& result, const Model& model,
                        const ContactNodeValues& values);

}  // namespace signorini
