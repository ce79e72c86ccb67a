#pragma once
// The result files of a run, written together once the solve is over: <outdir>/summary.json,
// contact.csv, solution.vtu and contact.vtu (docs/output.md), atomically and as a set
// (output/atomic_file.hpp), so that a failed run leaves the results of an earlier one intact.

#include <filesystem>
#include <string>
#include <vector>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/problem/model.hpp"
#include "signorini/problem/problem_spec.hpp"
#include "signorini/problem/resultants.hpp"

namespace signorini {

/// Creates `outdir` if needed (InputError "cannot create output folder '<dir>': <reason>") and
/// writes summary.json, contact.csv, solution.vtu and contact.vtu into it (InputError "cannot
/// write '<path>': <reason>").
void write_results(const std::filesystem::path& outdir, const ContactResult& result,
                   const Model& model, const ProblemSpec& spec);
/// As above, with the resultants the caller has already computed (problem/resultants.hpp).
void write_results(const std::filesystem::path& outdir, const ContactResult& result,
                   const Model& model, const ProblemSpec& spec, const Resultants& resultants);

/// One step of a loading history (problem/load_stepping.hpp): <outdir>/steps/solution_NNNN.vtu
/// and contact_NNNN.csv (NNNN the step number from 0001), written as a set, and
/// <outdir>/solution.pvd, the time series of the steps so far for ParaView (time = the step
/// number), replaced after each step. Errors as write_results.
void write_load_step(const std::filesystem::path& outdir, int step, const ContactResult& result,
                     const Model& model);

/// The file names of step `step` relative to the output folder ("steps/solution_0003.vtu").
std::string load_step_file(const std::string& stem, int step, const std::string& extension);

/// The pieces that a distributed run's `<stem>.pvtu` names (docs/distributed.md, "Results"):
/// `<stem>_<rank>.vtu` for each of `ranks` ranks, or on one rank `<stem>.vtu` itself.
std::vector<std::string> solution_pieces(const std::string& stem, int ranks);

/// Creates a folder and its parents; throws InputError "cannot create output folder ...". Called
/// by write_results; the tool also calls it before the solve, so that a bad -o fails fast.
void create_output_folder(const std::filesystem::path& outdir);

}  // namespace signorini
