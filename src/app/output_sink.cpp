#include "app/output_sink.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "curdle/error.h"

namespace fs = std::filesystem;

namespace curdle::app {

void OutputSink::write_via_file(const std::string& name,
                                const std::function<void(const fs::path&)>& fill) {
  std::string pattern = (fs::temp_directory_path() / "curdle-XXXXXX").string();
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0) throw std::runtime_error("cannot make a temporary file for " + name);
  ::close(fd);
  struct Remove {
    std::string path;
    ~Remove() { ::unlink(path.c_str()); }
  } remove{pattern};
  fill(pattern);
  std::ifstream in(pattern, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  write(name, [&](std::ostream& out) { out << bytes.str(); });
}

StagingDirectory::StagingDirectory(fs::path dir) : dir_(std::move(dir)) {
  // The nearest existing ancestor must be a directory we may write into; nothing is made yet,
  // so that a run that fails leaves no new directory behind.
  fs::path existing = fs::absolute(dir_).lexically_normal();
  std::error_code ec;
  while (!fs::exists(existing, ec) && existing.has_relative_path()) existing = existing.parent_path();
  if (!fs::is_directory(existing, ec))
    throw InputError("cannot create the output directory " + dir_.string() + ": " +
                     existing.string() + " is a file in the way");
  if (::access(existing.c_str(), W_OK) != 0)
    throw InputError("cannot create the output directory " + dir_.string() + ": " +
                     std::strerror(errno));
}

StagingDirectory::~StagingDirectory() {
  if (committed_) return;
  staged_.clear();  // removes the staged files
  std::error_code ec;
  for (auto it = made_.rbegin(); it != made_.rend(); ++it) fs::remove(*it, ec);  // if empty
}

void StagingDirectory::make_dir(const fs::path& dir) {
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path p = dir; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if (!p.has_relative_path() || p == p.parent_path()) break;
  }
  make_output_dir(dir);
  made_.insert(made_.end(), missing.rbegin(), missing.rend());
}

StagedFile& StagingDirectory::stage(const std::string& name) {
  const fs::path target = dir_ / name;
  make_dir(target.parent_path());
  staged_.push_back(std::make_unique<StagedFile>(target));
  return *staged_.back();
}

void StagingDirectory::write(const std::string& name,
                             const std::function<void(std::ostream&)>& fill) {
  stage(name).write(fill);
}

void StagingDirectory::write_via_file(const std::string& name,
                                      const std::function<void(const fs::path&)>& fill) {
  fill(stage(name).temporary());
}

void StagingDirectory::commit() {
  if (staged_.empty()) make_dir(dir_);  // a run with nothing to write still makes its directory
  for (auto& f : staged_) f->check_replaceable();
  for (auto& f : staged_) f->commit();
  committed_ = true;
}

std::vector<fs::path> StagingDirectory::files() const {
  std::vector<fs::path> files;
  for (const auto& f : staged_) files.push_back(f->target());
  return files;
}

void MemorySink::write(const std::string& name, const std::function<void(std::ostream&)>& fill) {
  std::ostringstream out;
  fill(out);
  files_[name] = std::move(out).str();
}

}  // namespace curdle::app
