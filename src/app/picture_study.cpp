#include "app/picture_study.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "app/measure_run.h"
#include "app/run.h"
#include "curdle/error.h"
#include "io/atomic_file.h"
#include "io/bounded_image.h"
#include "io/picture_gate.h"

namespace fs = std::filesystem;

namespace curdle::app {
namespace {

constexpr size_t kMaxUploadBytes = size_t{64} << 20;  // as a picture file read from disk

// The bytes in a file of this process's own (mode 0600), removed when it goes out of scope:
// OpenImageIO reads files, and finds the format by the extension first.
class TemporaryPicture {
 public:
  TemporaryPicture(const std::string& bytes, const std::string& extension) {
    const fs::path folder = temporary_folder();
    std::string pattern = (folder / "curdle-upload-XXXXXX").string();
    pattern += extension;
    const int fd = ::mkstemps(pattern.data(), static_cast<int>(extension.size()));
    if (fd < 0)
      throw InputError("cannot make a temporary file for the picture in " + folder.string() + ": " +
                       std::strerror(errno) + "; set TMPDIR to a folder this program may write to");
    path_ = pattern;
    size_t written = 0;
    while (written < bytes.size()) {
      const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
      if (n <= 0) {
        ::close(fd);
        ::unlink(path_.c_str());
        throw InputError("cannot write the picture to a temporary file in " + folder.string() +
                         " (is the disk full?)");
      }
      written += static_cast<size_t>(n);
    }
    ::close(fd);
  }
  ~TemporaryPicture() { ::unlink(path_.c_str()); }
  TemporaryPicture(const TemporaryPicture&) = delete;
  TemporaryPicture& operator=(const TemporaryPicture&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace

std::string upload_name(const std::string& name) {
  const size_t slash = name.find_last_of("/\\");
  std::string safe = slash == std::string::npos ? name : name.substr(slash + 1);
  if (safe.size() > 64) safe = safe.substr(safe.size() - 64);
  for (char& c : safe)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '-';
  if (safe.find_first_not_of(".-_") == std::string::npos) safe = "picture";
  return safe;
}

PictureStudy study_picture(const PictureStudyRequest& r) {
  const std::string name = upload_name(r.name);
  if (r.bytes.empty())
    throw InputError("the picture " + name + " is empty; send the picture's file");
  if (r.bytes.size() > kMaxUploadBytes)
    throw ResourceLimitError("the picture " + name + " is larger than 64 MiB");
  FitRequest fit;
  fit.source = name;
  fit.base = r.base;
  fit.stages = r.stages;
  fit.curds = r.curds;
  fit.states = r.states;
  // Options first: a wrong one is named before the picture is read (and before 2^curds).
  check_fit_options(fit);
  MeasureRequest measure;
  measure.image = name;
  measure.values = r.states > 0 ? r.states + 1 : 1 << r.curds;
  measure.base = r.base;
  check_measure_options(measure);
  // Saved under the ending of what its bytes are: nothing reads it by the name it was sent as.
  std::string why;
  const std::optional<PictureHeader> header = read_picture_header(r.bytes, why);
  if (!header)
    throw InputError("cannot read the picture " + name + ": " + why + " (" + kPictureFormats + ")");
  const TemporaryPicture file(r.bytes, std::string(".") + decoder_name(header->format));
  const LuminanceImage image = read_bounded_luminance(
      file.path(), "the picture", SourceLocation{},
      r.max_memory ? r.max_memory : default_memory_limit(), r.max_pixels, name);
  PictureStudy study;
  study.fitted = fit_picture(image, fit);
  study.measured = measure_picture(image, name, measure);
  return study;
}

}  // namespace curdle::app
