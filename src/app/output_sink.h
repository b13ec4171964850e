// Where a run's files go: a staging directory for the command line (every file renamed into
// place only once all are written), or memory for the server's downloads.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "export/atomic_file.h"

namespace curdle::app {

class OutputSink {
 public:
  virtual ~OutputSink() = default;
  // Writes the file `name` ("layout.svg", "sheets/S-R1-C1.dxf") through a stream.
  virtual void write(const std::string& name, const std::function<void(std::ostream&)>& fill) = 0;
  // For writers that can only write a named file (dxflib): `fill` writes the file at a path.
  virtual void write_via_file(const std::string& name,
                              const std::function<void(const std::filesystem::path&)>& fill);
};

// Stages every file beside its target in `dir`; commit() renames them all into place, and a
// sink destroyed before that removes what it staged, and the directories it made.
class StagingDirectory : public OutputSink {
 public:
  // Throws InputError when `dir` cannot be made or written; makes it at the first file.
  explicit StagingDirectory(std::filesystem::path dir);
  ~StagingDirectory() override;
  void write(const std::string& name, const std::function<void(std::ostream&)>& fill) override;
  void write_via_file(const std::string& name,
                      const std::function<void(const std::filesystem::path&)>& fill) override;
  void commit();
  std::vector<std::filesystem::path> files() const;  // in the order written
  const std::filesystem::path& dir() const { return dir_; }

 private:
  StagedFile& stage(const std::string& name);
  void make_dir(const std::filesystem::path& dir);
  std::filesystem::path dir_;
  std::vector<std::unique_ptr<StagedFile>> staged_;
  std::vector<std::filesystem::path> made_;  // directories this sink created, outermost first
  bool committed_ = false;
};

// Keeps every file in memory, by name.
class MemorySink : public OutputSink {
 public:
  void write(const std::string& name, const std::function<void(std::ostream&)>& fill) override;
  const std::map<std::string, std::string>& files() const { return files_; }

 private:
  std::map<std::string, std::string> files_;
};

}  // namespace curdle::app
