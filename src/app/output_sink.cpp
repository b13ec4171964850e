#include "app/output_sink.h"

#include <unistd.h>

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

StagingDirectory::StagingDirectory(fs::path dir) : dir_(std::move(dir)) { make_output_dir(dir_); }

StagedFile& StagingDirectory::stage(const std::string& name) {
  const fs::path target = dir_ / name;
  if (target.parent_path() != dir_) make_output_dir(target.parent_path());
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
  for (auto& f : staged_) f->check_replaceable();
  for (auto& f : staged_) f->commit();
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
