#include "io/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "curdle/error.h"

namespace curdle {
namespace fs = std::filesystem;

StagedFile::StagedFile(fs::path target) : target_(std::move(target)) {
  std::string name = ".";  // hidden, beside the target so that the rename stays on one disk
  name += target_.filename().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  temporary_ = target_.parent_path() / name;
}

StagedFile::~StagedFile() {
  if (!committed_) {
    std::error_code ec;
    fs::remove(temporary_, ec);
  }
}

void StagedFile::check_replaceable() const {
  std::error_code ec;
  if (fs::is_directory(target_, ec))
    throw InputError("cannot write " + target_.string() +
                     ": a directory of that name is in the way");
  // A device, a pipe or a socket is not ours to replace with a file.
  const fs::file_status status = fs::symlink_status(target_, ec);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw InputError("cannot write " + target_.string() +
                     ": it is not a regular file (a device, pipe, socket or link); name a new "
                     "file or a regular one to replace");
}

void StagedFile::commit() {
  std::error_code ec;
  fs::rename(temporary_, target_, ec);
  if (ec) throw InputError("cannot write " + target_.string() + ": " + ec.message());
  committed_ = true;
}

void write_stream(const fs::path& path, const fs::path& target,
                  const std::function<void(std::ostream&)>& write) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError("cannot write " + target.string() + ": " + std::strerror(errno));
  write(out);
  out.flush();
  if (!out) throw InputError("cannot write " + target.string() + ": " + std::strerror(errno));
}

void StagedFile::write(const std::function<void(std::ostream&)>& write) {
  write_stream(temporary_, target_, write);
}

void write_file(const fs::path& target, const std::function<void(std::ostream&)>& write) {
  StagedFile staged(target);
  staged.check_replaceable();
  staged.write(write);
  staged.commit();
}

void make_output_dir(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError("cannot create the output directory " + dir.string() + ": " +
                     (ec ? ec.message() : "a file of that name is in the way"));
  if (::access(dir.c_str(), W_OK) != 0)
    throw InputError("cannot write into the output directory " + dir.string() + ": " +
                     std::strerror(errno));
}

std::filesystem::path temporary_folder() {
  std::error_code ec;
  const std::filesystem::path folder = std::filesystem::temp_directory_path(ec);
  if (ec) {
    const char* named = std::getenv("TMPDIR");
    throw InputError(
        std::string("cannot make a temporary file: ") +
        (named ? std::string("TMPDIR names ") + named + ", which is not a folder" : ec.message()) +
        "; set TMPDIR to a folder this program may write to");
  }
  return folder;
}

}  // namespace curdle
