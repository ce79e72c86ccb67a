#include "signorini/output/contact_csv.hpp"

#include <fmt/format.h>

#include "signorini/core/error.hpp"
#include "signorini/interface/tangent_basis.hpp"

namespace signorini {

namespace {

// The boundary's name, quoted as CSV wants when it holds a comma or a quote.
std::string csv_name(const std::string& name) {
  if (name.find_first_of(",\"\n") == std::string::npos) return name;
  std::string quoted = "\"";
  for (const char ch : name) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

// Friction's columns, appended to a row: the tangential multiplier (as the pressure is
// -(sigma n) . nu, this is the tangential part of -sigma n: along the slip where the node
// slides) and the node's state. In 2D one component along tau, in 3D a Cartesian vector.
struct FrictionColumns {
  const Model& model;
  const ContactResult& result;
  std::vector<FrictionState> states;
  Matrix cartesian;  // 3D: the tangential traction as a Cartesian vector per node
  FrictionColumns(const Model& m, const ContactResult& r)
      : model(m),
        result(r),
        states(on() ? friction_states(contact_law(m.problem), r.l, r.tangential)
                    : std::vector<FrictionState>{}),
        cartesian(on() && m.mesh.dim() == 3
                      ? cartesian_tangential(m.problem.contact.normals, r.tangential)
                      : Matrix()) {}
  /// Whether the law has tangential rows (friction).
  [[nodiscard]] bool on() const { return contact_law(model.problem).components() > 1; }
  [[nodiscard]] std::string header() const {
    if (!on()) return "";
    return model.mesh.dim() == 2 ? ",tangential,slip,state"
                                 : ",tangential_x,tangential_y,tangential_z,slip,state";
  }
  [[nodiscard]] std::string row(Index j) const {
    if (!on()) return "";
    const std::string_view state =
        enum_to_string(kFrictionStateNames, states[static_cast<std::size_t>(j)]);
    const double slip = result.slip.size() > j ? result.slip(j) : 0.0;
    if (model.mesh.dim() == 2)
      return fmt::format(",{:.17g},{:.17g},{}", result.tangential(0, j) + 0.0, slip, state);
    return fmt::format(",{:.17g},{:.17g},{:.17g},{:.17g},{}", cartesian(0, j) + 0.0,
                       cartesian(1, j) + 0.0, cartesian(2, j) + 0.0, slip, state);
  }
};

// 3D: a surface has no single tangential direction, so the tangential displacement is given as
// the Cartesian vector u - u_n nu; no arc length.
std::string contact_csv_3d(const ContactResult& result, const Model& model,
                           const ContactNodeValues& values) {
  const ContactSet& c = model.problem.contact;
  const FrictionColumns friction(model, result);
  std::string out =
      "x,y,z,u_n,u_tx,u_ty,u_tz,pressure,gap,n_x,n_y,n_z,boundary" + friction.header() + "\n";
  for (std::size_t part = 0; part < model.contact_boundaries.size(); ++part) {
    const std::string name = csv_name(model.contact_boundaries[part]);
    for (Index j = model.contact_starts[part]; j < model.contact_starts[part + 1]; ++j) {
      const Eigen::Vector3d uj = values.displacement.col(j);
      const Eigen::Vector3d n = c.normals.col(j);
      const double un = uj.dot(n);
      const Eigen::Vector3d ut = uj - un * n;
      const double gap = c.gaps(j) + n.dot(values.prescribed.col(j));
      const Eigen::Vector3d x = values.points.col(j);
      out += fmt::format(
          "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},"
          "{:.17g},{}{}\n",
          x(0), x(1), x(2), un, ut(0) + 0.0, ut(1) + 0.0, ut(2) + 0.0, result.l(j), gap, n(0) + 0.0,
          n(1) + 0.0, n(2) + 0.0, name, friction.row(j));
    }
  }
  return out;
}

}  // namespace

std::string contact_csv(const ContactResult& result, const Model& model) {
  return contact_csv(result, model, contact_node_values(model, result));
}

std::string contact_csv(const ContactResult& result, const Model& model,
                        const ContactNodeValues& values) {
  if (model.mesh.dim() == 3) return contact_csv_3d(result, model, values);
  const ContactSet& c = model.problem.contact;
  const FrictionColumns friction(model, result);
  std::string out = "x,y,u_n,u_t,pressure,gap,n_x,n_y,s,boundary" + friction.header() + "\n";
  // s: the arc length along the contact nodes of each contact boundary in their order (chords
  // between consecutive nodes, so along a quadratic edge through its middle node), from 0 at the
  // start of each.
  for (std::size_t part = 0; part < model.contact_boundaries.size(); ++part) {
    const std::string name = csv_name(model.contact_boundaries[part]);
    const Index first = model.contact_starts[part];
    double s = 0.0;
    for (Index j = first; j < model.contact_starts[part + 1]; ++j) {
      if (j > first) s += (values.points.col(j) - values.points.col(j - 1)).norm();
      const double ux = values.displacement(0, j);
      const double uy = values.displacement(1, j);
      const double nx = c.normals(0, j);
      const double ny = c.normals(1, j);
      // The initial gap: the contact set's g_j has the prescribed components of the node taken
      // off (interface/contact_boundary.cpp); u_n here is the whole normal displacement.
      const double gap = c.gaps(j) + c.normals.col(j).dot(values.prescribed.col(j));
      const Eigen::Vector2d x = values.points.col(j);
      out += fmt::format(
          "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{}{}\n", x(0),
          x(1), ux * nx + uy * ny, -ux * ny + uy * nx, result.l(j), gap, nx + 0.0, ny + 0.0, s,
          name, friction.row(j));
    }
  }
  return out;
}

}  // namespace signorini
