// Where a run's files go: a staging directory for the command line (every file renamed into
// place only once all are written), or memory for the server's downloads.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "io/atomic_file.h"

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

// Writes a set of files into `dir`, replaced whole or not at all. While the run writes, the
// new set is staged in a hidden directory beside `dir`; commit() swaps it in with one rename
// (renameat2 RENAME_EXCHANGE) and removes the old set. A directory that also holds files this
// program did not write (`is_output` says which it writes) keeps them: there each file is
// staged beside its target and renamed into place. A sink destroyed before commit() removes
// everything it staged and the directories it made.
class StagingDirectory : public OutputSink {
 public:
  explicit StagingDirectory(std::filesystem::path dir,
                            std::function<bool(const std::string&, bool folder)> is_output = {});
  ~StagingDirectory() override;
  void write(const std::string& name, const std::function<void(std::ostream&)>& fill) override;
  void write_via_file(const std::string& name,
                      const std::function<void(const std::filesystem::path&)>& fill) override;
  void commit();
  std::vector<std::filesystem::path> files() const;  // the targets, by name
  const std::filesystem::path& dir() const { return dir_; }
  bool replaces_whole() const { return whole_; }

 private:
  std::filesystem::path prepare(const std::string& name);  // where to write `name` now
  void make_dir(const std::filesystem::path& dir);
  std::filesystem::path dir_, staging_;
  std::filesystem::path place_;  // the directory itself: dir_, or where its link points
  std::optional<std::pair<dev_t, ino_t>> found_;  // what held place_ when the run began
  bool whole_ = false;
  std::vector<std::string> names_;
  std::vector<std::unique_ptr<StagedFile>> staged_;  // beside their targets (not whole)
  std::vector<std::filesystem::path> made_;  // directories this sink created, outermost first
  bool committed_ = false;
};

// After SIGINT or SIGTERM: removes every staged file and directory of every sink, and blocks
// any new one, so that the process can end at once leaving nothing behind. Call it from a
// thread (not a signal handler), then end the process.
void remove_staged_files_for_exit();

// Keeps every file in memory, by name.
class MemorySink : public OutputSink {
 public:
  void write(const std::string& name, const std::function<void(std::ostream&)>& fill) override;
  const std::map<std::string, std::string>& files() const { return files_; }

 private:
  std::mutex mutex_;  // writers run side by side
  std::map<std::string, std::string> files_;
};

}  // namespace curdle::app
