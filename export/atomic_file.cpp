#include "export/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "curdle/error.h"

namespace curdle {
namespace fs = std::filesystem;

StagedFile::StagedFile(fs::path target) : target_(std::move(target)) {
  temporary_ = target_.parent_path() /
               ("." + target_.filename().string() + ".tmp-" + std::to_string(::getpid()));
}

StagedFile::~StagedFile() {
  if (!committed_) {
    std::error_code ec;
    fs::remove(temporary_, ec);
  }
}

void StagedFile::commit() {
  std::error_code ec;
  fs::rename(temporary_, target_, ec);
  if (ec) throw InputError("cannot write " + target_.string() + ": " + ec.message());
  committed_ = true;
}

void write_file(const fs::path& target, const std::function<void(std::ostream&)>& write) {
  StagedFile staged(target);
  {
    std::ofstream out(staged.temporary(), std::ios::binary | std::ios::trunc);
    if (!out)
      throw InputError("cannot write " + target.string() + ": " + std::strerror(errno));
    write(out);
    out.flush();
    if (!out) throw InputError("cannot write " + target.string() + ": " + std::strerror(errno));
  }
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

}  // namespace curdle
