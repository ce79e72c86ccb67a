#pragma once
// Writing result files so that readers only ever see a complete file: the contents go to a
// temporary file in the same folder, which is then renamed over the target (rename() within one
// file system is atomic). A run that fails part-way leaves no half-written file and keeps the
// results of an earlier run.

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace signorini {

/// Replaces `path` by a file holding `contents`. The folder must exist. Throws InputError
/// "cannot write '<path>': <reason>"; the earlier file, if any, is then left as it was.
void write_file_atomically(const std::filesystem::path& path, const std::string& contents);

/// Replaces several files together: every temporary file is written and flushed before the first
/// is renamed, so that a failure while writing (a full disk, a folder that cannot be written)
/// leaves every earlier file as it was, never a mix of old and new results. Errors as
/// write_file_atomically.
void write_files_atomically(
    const std::vector<std::pair<std::filesystem::path, std::string>>& files);

/// The two halves of write_files_atomically, for writers that must agree before any file is
/// replaced (the ranks of a distributed run, docs/distributed.md): add() writes and flushes a
/// temporary file (throwing as write_file_atomically), commit() renames them all; the
/// temporaries not committed are removed when the object goes.
class StagedFiles {
 public:
  StagedFiles();
  ~StagedFiles();
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;
  void add(const std::filesystem::path& path, const std::string& contents);
  void commit();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace signorini
