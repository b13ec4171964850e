// Outputs are written under a temporary name beside the target and renamed into place, so a
// failure never leaves half a file. Errors writing become InputError naming the path.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace curdle {

class StagedFile {
 public:
  explicit StagedFile(std::filesystem::path target);
  ~StagedFile();  // removes the temporary file unless committed
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;

  const std::filesystem::path& temporary() const { return temporary_; }
  const std::filesystem::path& target() const { return target_; }
  // Writes the temporary file through a stream; InputError naming the target on failure.
  void write(const std::function<void(std::ostream&)>& write);
  // Throws InputError when the target could not be replaced (it is a directory), so that a
  // set of files can be checked before any of them is renamed into place.
  void check_replaceable() const;
  void commit();  // renames the temporary file onto the target

 private:
  std::filesystem::path target_, temporary_;
  bool committed_ = false;
};

// Writes exactly `path` through a stream (no staging); InputError naming `target` (the file
// the user will see) when it cannot be written.
void write_stream(const std::filesystem::path& path, const std::filesystem::path& target,
                  const std::function<void(std::ostream&)>& write);

// Writes `target` through a stream, atomically.
void write_file(const std::filesystem::path& target,
                const std::function<void(std::ostream&)>& write);

// Creates `dir` and its parents, or throws InputError saying why it cannot.
void make_output_dir(const std::filesystem::path& dir);

// The folder temporary files go in (TMPDIR, else /tmp); InputError saying so, and what to do,
// when it is not a folder.
std::filesystem::path temporary_folder();

}  // namespace curdle
