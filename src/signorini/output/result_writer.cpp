#include "signorini/output/result_writer.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "signorini/contact/distributed_engine.hpp"
#include "signorini/core/error.hpp"
#include "signorini/fem/rigid_body_modes.hpp"
#include "signorini/output/atomic_file.hpp"
#include "signorini/output/contact_csv.hpp"
#include "signorini/output/solution_vtu.hpp"
#include "signorini/output/summary_json.hpp"

namespace signorini {

void create_output_folder(const std::filesystem::path& outdir) {
  std::error_code ec;
  std::filesystem::create_directories(outdir, ec);
  // create_directories reports no error when the path exists as a file: check what is there.
  if (!ec && !std::filesystem::is_directory(outdir, ec) && !ec)
    ec = std::make_error_code(std::errc::not_a_directory);
  if (ec)
    throw InputError("cannot create output folder '" + outdir.string() + "': " + ec.message());
}

std::string load_step_file(const std::string& stem, int step, const std::string& extension) {
  return fmt::format("steps/{}_{:04d}.{}", stem, step, extension);
}

namespace {

// The .pvd collection of the steps 1 to `step`, whose files are steps/solution_<k>.<extension>.
std::string step_collection(int step, const std::string& extension) {
  std::string pvd =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (int k = 1; k <= step; ++k)
    pvd += fmt::format("  <DataSet timestep=\"{}\" part=\"0\" file=\"{}\"/>\n", k,
                       load_step_file("solution", k, extension));
  pvd += "</Collection>\n</VTKFile>\n";
  return pvd;
}

// This rank's piece `<stem>_<rank>.vtu` of a solution in `folder`: the cells that the rank
// accounts for (Model::cell_rank, by its range of the free dofs: contact/distributed_engine.hpp,
// partition_of), and on rank 0 the `<stem>.pvtu` that names the pieces. On a rank's part of the
// mesh (Model::is_part) the cells of the part that the rank writes.
void stage_pieces(StagedFiles& staged, const std::filesystem::path& folder, const std::string& stem,
                  const ContactResult& result, const Model& model, int rank, int ranks) {
  const std::vector<Index> starts = partition_of(model.problem, ranks);
  std::vector<Index> cells;
  for (Index c = 0; c < model.mesh.num_cells(); ++c)
    if (model.cell_rank(c, starts) == rank) cells.push_back(c);
  const std::vector<std::string> pieces = solution_pieces(stem, ranks);
  std::string pvtu;
  staged.add(folder / pieces[static_cast<std::size_t>(rank)],
             solution_vtu_piece(result, model, cells, pieces, rank == 0 ? &pvtu : nullptr));
  if (rank == 0) staged.add(folder / (stem + ".pvtu"), pvtu);
}

// Every rank stages its files, and the renames follow only when all have, so that a failure on
// any rank leaves the earlier results whole. `stage` adds this rank's files.
template <class Stage>
void write_on_every_rank(const std::filesystem::path& outdir, const DistributedEngine& engine,
                         const Stage& stage) {
  StagedFiles staged;
  std::string error;
  try {
    stage(staged);
  } catch (const InputError& e) {
    error = e.what();
  }
  if (engine.any(!error.empty())) {
    if (!error.empty()) throw InputError(error);
    throw InputError(fmt::format(
        "another MPI rank could not write its piece of the results in '{}'; nothing was "
        "replaced",
        outdir.string()));
  }
  staged.commit();
}

}  // namespace

std::vector<std::string> solution_pieces(const std::string& stem, int ranks) {
  // One rank: its piece is the whole solution, `<stem>.vtu` (a copy as `<stem>_0.vtu` cost
  // another 70 MB at a million unknowns).
  if (ranks == 1) return {stem + ".vtu"};
  std::vector<std::string> pieces;
  for (int r = 0; r < ranks; ++r) pieces.push_back(fmt::format("{}_{}.vtu", stem, r));
  return pieces;
}

void write_load_step(const std::filesystem::path& outdir, int step, const ContactResult& result,
                     const Model& model) {
  if (model.is_part()) {
    // A distributed run on the ranks' parts of the mesh (docs/distributed.md): each rank writes
    // its piece of the step's solution, rank 0 the .pvtu that names them, the step's
    // contact.csv and solution.pvd.
    const DistributedEngine& engine = required_engine(model.problem);
    const ContactNodeValues values = contact_node_values(model, result);
    write_on_every_rank(outdir, engine, [&](StagedFiles& staged) {
      create_output_folder(outdir / "steps");
      stage_pieces(staged, outdir / "steps", fmt::format("solution_{:04d}", step), result, model,
                   engine.rank(), engine.size());
      if (engine.rank() != 0) return;
      staged.add(outdir / load_step_file("contact", step, "csv"),
                 contact_csv(result, model, values));
      staged.add(outdir / "solution.pvd", step_collection(step, "pvtu"));
    });
    return;
  }
  create_output_folder(outdir / "steps");
  write_files_atomically(
      {{outdir / load_step_file("solution", step, "vtu"), solution_vtu(result, model)},
       {outdir / load_step_file("contact", step, "csv"), contact_csv(result, model)}});
  write_file_atomically(outdir / "solution.pvd", step_collection(step, "vtu"));
}

void write_results(const std::filesystem::path& outdir, const ContactResult& result,
                   const Model& model, const ProblemSpec& spec) {
  write_results(outdir, result, model, spec, compute_resultants(model, result));
}

namespace {

// A distributed run (docs/distributed.md): every rank writes its piece solution_<rank>.vtu; rank
// 0 writes solution.pvtu, summary.json, contact.csv and contact.vtu (from the contact nodes'
// values that the ranks give together), and, where it holds the whole mesh, the whole
// solution.vtu too (on one rank, as its piece).
void write_distributed(const std::filesystem::path& outdir, const ContactResult& result,
                       const Model& model, const ProblemSpec& spec, const Resultants& resultants,
                       const DistributedEngine& engine) {
  const ContactNodeValues values = contact_node_values(model, result);
  write_on_every_rank(outdir, engine, [&](StagedFiles& staged) {
    stage_pieces(staged, outdir, "solution", result, model, engine.rank(), engine.size());
    if (engine.rank() != 0) return;
    staged.add(outdir / "summary.json",
               summary_to_json(result, model, spec, resultants).dump(2) + "\n");
    staged.add(outdir / "contact.csv", contact_csv(result, model, values));
    // (Where every rank holds the whole mesh; on one rank its piece is solution.vtu.)
    if (!model.is_part() && engine.size() > 1)
      staged.add(outdir / "solution.vtu", solution_vtu(result, model));
    staged.add(outdir / "contact.vtu", contact_vtu(result, model, values));
  });
}

}  // namespace

void write_results(const std::filesystem::path& outdir, const ContactResult& result,
                   const Model& model, const ProblemSpec& spec, const Resultants& resultants) {
  create_output_folder(outdir);
  if (const DistributedEngine* engine = model.problem.engine;
      engine != nullptr && result.summary.path == SolvePath::Distributed) {
    write_distributed(outdir, result, model, spec, resultants, *engine);
    return;
  }
  // Every content is made before any file is touched, and the files are replaced together: an
  // error leaves the results of an earlier run as they were, never a mix of old and new.
  std::vector<std::pair<std::filesystem::path, std::string>> files;
  files.emplace_back(outdir / "summary.json",
                     summary_to_json(result, model, spec, resultants).dump(2) + "\n");
  files.emplace_back(outdir / "contact.csv", contact_csv(result, model));
  files.emplace_back(outdir / "solution.vtu", solution_vtu(result, model));
  files.emplace_back(outdir / "contact.vtu", contact_vtu(result, model));
  write_files_atomically(files);
}

}  // namespace signorini
