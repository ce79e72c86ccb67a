#pragma once
// contact.csv: the solution along the contact boundary Gamma_K, one row per contact node in the
// order of the ContactSet (along the boundary part): what the paper's Figures 2 and 3 plot.

#include <string>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/problem/contact_node_values.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {

/// Header "x,y,u_n,u_t,pressure,gap,n_x,n_y", then per contact node j: its coordinates, the normal
/// displacement u.nu_j, the tangential displacement u.tau_j with tau_j = (-nu_y, nu_x) (nu turned
/// a quarter counterclockwise: on a bottom edge, nu = (0, -1) and tau = (1, 0)), the contact
/// pressure l_j >= 0, the gap g_j and the outward unit normal nu_j (the foundation lies at
/// x_j + g_j nu_j). Numbers with 17 significant digits, so that they read back
/// exactly. In 3D: x,y,z,u_n,u_tx,u_ty,u_tz,pressure,gap,n_x,n_y,n_z,boundary. With friction
/// (Model::friction) the columns `tangential` (3D: tangential_x, _y, _z), the tangential part of
/// -sigma n as the pressure is its normal part (along the slip where the node slides), and
/// `state` (separated, sticking, sliding) follow.
/// On a rank's part of the mesh (Model::is_part) a collective call: contact_node_values.
std::string contact_csv(const ContactResult& result, const Model& model);
/// The same from the contact nodes' values made once (contact_node_values).
std::string contact_csv(const ContactResult& result, const Model& model,
                        const ContactNodeValues& values);

}  // namespace signorini
