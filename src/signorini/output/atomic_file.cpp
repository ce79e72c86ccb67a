#include "signorini/output/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <memory>
#include <vector>

#include "signorini/core/error.hpp"

namespace signorini {

namespace {

// Owns the temporary file until it has been renamed, so that every failure path removes it.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::filesystem::path& target) {
    // A name no other writer uses (process id and a per-process counter; O_EXCL guards against
    // leftovers), so that two runs writing the same folder cannot clobber each other's
    // temporaries. The leading dot hides it from casual listings. Mode 0666 less the umask, as
    // any file the user creates.
    static std::atomic<unsigned> counter{0};
    for (int attempt = 0; attempt < 100; ++attempt) {
      // fmt rather than operator+ chains: GCC 12 warns falsely (-Wrestrict) on "." + string.
      const std::string name =
          fmt::format(".{}.tmp.{}.{}", target.filename().string(), ::getpid(), counter++);
      const std::string candidate = (target.parent_path() / name).string();
      fd_ = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd_ >= 0) {
        path_ = candidate;
        return;
      }
      if (errno != EEXIST) return;
    }
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!path_.empty()) ::unlink(path_.c_str());
  }

  [[nodiscard]] int fd() const { return fd_; }
  [[nodiscard]] const std::string& path() const { return path_; }
  /// Closes the descriptor; returns false (errno set) if the data could not be flushed.
  bool close() {
    const int rc = ::close(fd_);
    fd_ = -1;
    return rc == 0;
  }
  /// The file has been renamed: nothing left to remove.
  void release() { path_.clear(); }

 private:
  int fd_ = -1;
  std::string path_;
};

// Writes and flushes `contents` into a fresh temporary file beside `path`; the caller renames it.
std::unique_ptr<TemporaryFile> write_temporary(const std::filesystem::path& path,
                                               const std::string& contents) {
  const auto fail = [&](int error) {
    return InputError("cannot write '" + path.string() + "': " + std::strerror(error));
  };
  if (path.filename().empty())
    throw InputError("cannot write '" + path.string() + "': not a file name");

  auto tmp = std::make_unique<TemporaryFile>(path);
  if (tmp->fd() < 0) throw fail(errno);

  const char* data = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(tmp->fd(), data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw fail(errno);
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  // The data must be on disk before the rename makes it visible under the final name; otherwise
  // a crash right after could leave an empty file in place of the earlier results.
  if (::fsync(tmp->fd()) != 0) throw fail(errno);
  if (!tmp->close()) throw fail(errno);
  return tmp;
}

void rename_into_place(TemporaryFile& tmp, const std::filesystem::path& path) {
  if (::rename(tmp.path().c_str(), path.c_str()) != 0)
    throw InputError("cannot write '" + path.string() + "': " + std::strerror(errno));
  tmp.release();
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path, const std::string& contents) {
  const auto tmp = write_temporary(path, contents);
  rename_into_place(*tmp, path);
}

void write_files_atomically(
    const std::vector<std::pair<std::filesystem::path, std::string>>& files) {
  StagedFiles staged;
  for (const auto& [path, contents] : files) staged.add(path, contents);
  staged.commit();
}

struct StagedFiles::Impl {
  std::vector<std::pair<std::filesystem::path, std::unique_ptr<TemporaryFile>>> files;
};

StagedFiles::StagedFiles() : impl_(std::make_unique<Impl>()) {}
StagedFiles::~StagedFiles() = default;

void StagedFiles::add(const std::filesystem::path& path, const std::string& contents) {
  impl_->files.emplace_back(path, write_temporary(path, contents));
}

void StagedFiles::commit() {
  // Only renames are left, which fail only if the folder changed under us since the temporaries
  // were created in it.
  for (auto& [path, tmp] : impl_->files) rename_into_place(*tmp, path);
  impl_->files.clear();
}

}  // namespace signorini
