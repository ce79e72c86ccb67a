#include "signorini/io/result_writer.hpp"

#include "signorini/core/error.hpp"
#include "signorini/io/atomic_file.hpp"
#include "signorini/io/contact_csv.hpp"
#include "signorini/io/solution_vtu.hpp"
#include "signorini/io/summary_json.hpp"

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

void write_results(const std::filesystem::path& outdir, const ContactResult& result,
                   const Model& model, const ProblemSpec& spec) {
  write_results(outdir, result, model, spec, compute_resultants(model, result.u, result.l));
}

void write_results(const std::filesystem::path& outdir, const ContactResult& result,
                   const Model& model, const ProblemSpec& spec, const Resultants& resultants) {
  create_output_folder(outdir);
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
