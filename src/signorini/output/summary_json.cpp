#include "signorini/output/summary_json.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "signorini/config.hpp"
#include "signorini/contact/contact_solver_option_table.hpp"
#include "signorini/input/problem_schema.hpp"
#include "signorini/linalg/linear_solver_option_table.hpp"

namespace signorini {

TimingTable run_timings(const Model& model, const SolveSummary& summary) {
  TimingTable t = model.timings;
  t.merge(summary.timings);
  return t;
}

double run_total_seconds(const Model& model, const SolveSummary& summary) {
  // solve_contact() times the whole solve as "contact solve"; without it (a summary from a
  // method called directly) the solver's own phases are all there is.
  const bool has_solve =
      std::any_of(summary.timings.phases().begin(), summary.timings.phases().end(),
                  [](const auto& p) { return p.first == "contact solve"; });
  return model.timings.total() +
         (has_solve ? summary.timings.seconds("contact solve") : summary.timings.total());
}

namespace {

// A vector of the problem's dimension; + 0.0 turns a negative zero (from -(0 * l)) into 0: "-0.0"
// in a file looks like a sign error.
nlohmann::json vector_json(const Eigen::Vector3d& v, int dim) {
  nlohmann::json a = nlohmann::json::array();
  for (int k = 0; k < dim; ++k) a.push_back(v(k) + 0.0);
  return a;
}

// The moment: a number (about z) in 2D, a vector in 3D.
nlohmann::json moment_json(const Eigen::Vector3d& m, int dim) {
  return dim == 2 ? nlohmann::json(m(2) + 0.0) : vector_json(m, dim);
}

nlohmann::json resultants_json(const Resultants& r, int dim) {
  nlohmann::json reactions = nlohmann::json::array();
  for (const ClampReaction& c : r.reactions)
    reactions.push_back({{"boundary", c.boundary},
                         {"force", vector_json(c.force, dim)},
                         {"moment", moment_json(c.moment, dim)}});
  return {{"reference", vector_json(r.reference, dim)},
          {"applied", vector_json(r.applied, dim)},
          {"applied_moment", moment_json(r.applied_moment, dim)},
          {"reactions", reactions},
          {"contact", vector_json(r.contact, dim)},
          {"contact_moment", moment_json(r.contact_moment, dim)},
          {"balance", vector_json(r.balance, dim)},
          {"moment_balance", moment_json(r.moment_balance, dim)},
          {"relative_balance", r.relative_balance},
          {"relative_moment_balance", r.relative_moment_balance}};
}

nlohmann::json option_json(const OptionValue& value) {
  if (const auto* x = std::get_if<double>(&value)) return *x;
  if (const auto* i = std::get_if<std::int64_t>(&value)) return *i;
  if (const auto* b = std::get_if<bool>(&value)) return *b;
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  if (const auto* v = std::get_if<std::vector<double>>(&value)) return *v;
  return "auto";  // a NumberOrAuto without a number
}

// A section's keys and values (region_values(), contact_values(), ...) as a JSON object.
nlohmann::json values_json(const std::vector<std::pair<std::string, OptionValue>>& values) {
  nlohmann::json entry = nlohmann::json::object();
  for (const auto& [key, value] : values) entry[key] = option_json(value);
  return entry;
}

// {key: value} for every option of `table` that lives in the struct.
template <class S>
nlohmann::json options_json(const OptionTable<S>& table, const S& s) {
  return values_json(table.values(s));
}

}  // namespace

nlohmann::json summary_to_json(const ContactResult& result, const Model& model,
                               const ProblemSpec& spec) {
  return summary_to_json(result, model, spec, compute_resultants(model, result));
}

nlohmann::json summary_to_json(const ContactResult& result, const Model& model,
                               const ProblemSpec& spec, const Resultants& resultants) {
  using nlohmann::json;
  const SolveSummary& summary = result.summary;
  const int dim = model.mesh.dim();
  json j;
  j["signorini_version"] = SIGNORINI_VERSION;
  j["converged"] = summary.converged();
  j["termination"] = std::string(enum_to_string(kTerminationNames, summary.termination));
  j["message"] = summary.message;
  j["method"] = std::string(enum_to_string(kContactMethodNames, summary.method));
  j["path"] = std::string(enum_to_string(kSolvePathNames, summary.path));
  if (!summary.path_reason.empty()) j["path_reason"] = summary.path_reason;
  j["threads"] = summary.threads;
  j["ranks"] = summary.ranks;
  j["warm_started"] = summary.warm_started;
  j["M"] = summary.lagrangian;
  j["energy"] = summary.energy;
  j["strain_energy"] = resultants.strain_energy;
  // The method's own words (outer and inner steps: Uzawa and GNM, semismooth Newton steps and
  // the one linear solve of each, classical Uzawa steps), and the paper's names for the same.
  j["outer_iterations"] = summary.outer_iterations;
  j["uzawa_iterations"] = summary.outer_iterations;
  j["active_set_finish"] = summary.active_set_finish;
  if (!summary.load_steps.empty()) {
    json steps = json::array();
    for (const LoadStepRecord& s : summary.load_steps)
      steps.push_back({{"factor", s.factor},
                       {"converged", s.converged},
                       {"outer_iterations", s.outer_iterations},
                       {"n_active", s.active},
                       {"contact_force", s.contact_force},
                       {"seconds", s.seconds}});
    j["load_steps"] = steps;
  }

  json gnm = json::array(), armijo = json::array(), active = json::array(), dual = json::array(),
       linear = json::array(), factorizations = json::array(), updates = json::array();
  for (const OuterStepRecord& s : summary.steps) {
    gnm.push_back(s.inner_iterations);
    armijo.push_back(s.armijo_reductions);
    active.push_back(s.active_set_size);
    dual.push_back(s.dual_change);
    linear.push_back(s.linear_iterations);
    factorizations.push_back(s.factorizations);
    updates.push_back(s.factor_updates);
  }
  j["inner_iterations"] = gnm;
  j["gnm_iterations"] = gnm;
  j["armijo_reductions"] = armijo;
  j["active_set_sizes"] = active;
  j["dual_changes"] = dual;
  j["linear_iterations"] = linear;
  j["factorizations"] = factorizations;
  j["factor_updates"] = updates;
  if (summary.method == ContactMethod::ClassicalUzawa) j["classical_step"] = summary.classical_step;
  if (summary.method == ContactMethod::UzawaGnm) {
    j["r"] = summary.r;
    j["r_automatic"] = summary.r_automatic;
  }
  j["kkt_tolerance"] = summary.kkt_tolerance;
  if (!summary.device.empty()) {  // the backend path (docs/gpu.md)
    j["device"] = summary.device;
    j["device_peak_bytes"] = summary.device_peak_bytes;
    j["multigrid_levels"] = summary.multigrid_levels;
    if (summary.multigrid_levels.size() > 1)
      j["multigrid_coarsening"] =
          std::string(enum_to_string(kHierarchyKindNames, summary.multigrid_hierarchy));
  }

  j["n_dofs"] = model.num_dofs();
  j["n_free_dofs"] = model.dofs.num_free();
  j["n_contact_nodes"] = model.problem.contact.size();
  j["n_active"] = summary.num_active;
  j["contact_force"] = summary.contact_force;
  j["contact_force_vector"] = vector_json(summary.contact_force_vector, dim);
  j["resultants"] = resultants_json(resultants, dim);
  json point_loads = json::array();
  for (const PlacedPointLoad& p : model.point_loads)
    point_loads.push_back({{"requested", vector_json(p.requested, dim)},
                           {"node", p.node},
                           {"at", vector_json(p.at, dim)},
                           {"distance", p.distance},
                           {"force", vector_json(p.force, dim)}});
  j["point_loads"] = point_loads;
  j["kkt"] = {{"equilibrium", summary.kkt.equilibrium},
              {"penetration", summary.kkt.penetration},
              {"sign", summary.kkt.sign},
              {"complementarity", summary.kkt.complementarity}};
  if (const ContactLaw& law = contact_law(model.problem); law.components() > 1) {
    j["kkt"]["friction_bound"] = summary.kkt.friction_bound;
    j["kkt"]["slip"] = summary.kkt.slip;
    j["friction"] = {{"law", std::string(law.name())}};
    std::array<Index, 3> counts{};
    for (const FrictionState s : friction_states(law, result.l, result.tangential))
      ++counts[static_cast<std::size_t>(s)];
    for (const FrictionState s :
         {FrictionState::Separated, FrictionState::Sticking, FrictionState::Sliding})
      j["friction"][std::string(enum_to_string(kFrictionStateNames, s))] =
          counts[static_cast<std::size_t>(s)];
  }

  json timings = json::object();
  const TimingTable phases = run_timings(model, summary);  // named: phases() refers into it
  for (const auto& [phase, seconds] : phases.phases()) timings[phase] = seconds;
  timings["total"] = run_total_seconds(model, summary);
  j["timings"] = timings;

  // The settings, from the option tables (as the effective settings are); the sections of
  // formulas say how each was given.
  json problem = options_json(top_level_options(), spec);
  problem["units"] = spec.units.empty() ? json(nullptr) : json(spec.units);
  if (spec.mesh_type == MeshType::Given) {
    // A mesh the program gave (mesh/mesh_arrays.hpp): no keys say it, its sizes do.
    problem["mesh"] = {{"type", "given"}};
    if (spec.given_mesh) {
      problem["mesh"]["nodes"] = spec.given_mesh->num_nodes();
      problem["mesh"]["cells"] = spec.given_mesh->num_cells();
    }
  } else {
    problem["mesh"] = options_json(mesh_options(), spec);
  }
  problem["material"] = options_json(material_options(), spec);
  if (!spec.region_materials.empty()) {
    problem["region"] = json::array();
    for (const RegionMaterialSpec& m : spec.region_materials)
      problem["region"].push_back(values_json(region_values(m)));
  }
  problem["fem"] = options_json(fem_options(), spec);
  json clamps = json::array();
  for (const ClampSpec& c : spec.clamps) {
    json components = json::array();
    if (c.components[0]) components.push_back("x");
    if (c.components[1]) components.push_back("y");
    if (c.components[2] && dim == 3) components.push_back("z");
    clamps.push_back({{"boundary", c.boundary}, {"components", components}});
    if (c.at)
      clamps.back()["at"] = std::vector<double>(c.at->data(), c.at->data() + (dim == 3 ? 3 : 2));
  }
  problem["clamp"] = clamps;
  if (!spec.displacements.empty()) {
    problem["displacement"] = json::array();
    for (const DisplacementSpec& d : spec.displacements)
      problem["displacement"].push_back(values_json(displacement_values(d)));
  }
  json tractions = json::array();
  for (const TractionSpec& t : spec.tractions) {
    json tr = {{"boundary", t.boundary}, {"p", t.description}};
    if (std::isfinite(t.region.lower[0])) tr["x_range"] = {t.region.lower[0], t.region.upper[0]};
    if (std::isfinite(t.region.lower[1])) tr["y_range"] = {t.region.lower[1], t.region.upper[1]};
    if (!t.factors.empty()) tr["factors"] = t.factors;
    tractions.push_back(tr);
  }
  problem["traction"] = tractions;
  if (!spec.pressures.empty()) {
    problem["pressure"] = json::array();
    for (const PressureSpec& p : spec.pressures)
      problem["pressure"].push_back(values_json(pressure_values(p)));
  }
  if (spec.body_force) {
    problem["body_force"] = {{"f", spec.body_force_description}};
    if (!spec.body_force_factors.empty())
      problem["body_force"]["factors"] = spec.body_force_factors;
  }
  // One contact boundary as the object of [contact], several as the array of [[contact]].
  json contacts = json::array();
  for (const ContactSpec& c : spec.contacts) {
    contacts.push_back(values_json(contact_values(c, c.description, dim)));
    if (!c.surface_normal_text.empty()) contacts.back()["surface_normal"] = c.surface_normal_text;
  }
  problem["contact"] = contacts.size() == 1 ? contacts[0] : contacts;
  if (!spec.load_factors.empty()) problem["loading"] = {{"factors", spec.load_factors}};
  problem["solver"] = options_json(contact_solver_option_table(), spec.solver);
  problem["solver"]["linear"] = options_json(linear_solver_option_table(), spec.solver.linear);
  j["problem"] = problem;
  return j;
}

}  // namespace signorini
