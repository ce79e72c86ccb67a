#include "signorini/io/result_writer.hpp"

#include "signorini/core/error.hpp"
#include "signorini/io/atomic_file.hpp"
#include "signorini/io/contact_csv.hpp"
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
  create_output_folder(outdir);
  // Both contents are made before either file is touched: an error in one leaves both as they were.
  const std::string json = summary_to_json(result.summary, model, spec).dump(2) + "\n";
  const std::string csv = contact_csv(result, model);
  write_file_atomically(outdir / "summary.json", json);
  write_file_atomically(outdir / "contact.csv", csv);
}

}  // namespace signorini
