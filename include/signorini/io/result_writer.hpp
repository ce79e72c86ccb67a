#pragma once
// The result files of a run, written together once the solve is over: <outdir>/summary.json,
// contact.csv, solution.vtu and contact.vtu (docs/output.md), atomically and as a set
// (io/atomic_file.hpp), so that a failed run leaves the results of an earlier one intact.

#include <filesystem>

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

/// Creates a folder and its parents; throws InputError "cannot create output folder ...". Called
/// by write_results; the tool also calls it before the solve, so that a bad -o fails fast.
void create_output_folder(const std::filesystem::path& outdir);

}  // namespace signorini
