#include "io/bounded_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "curdle/error.h"

namespace curdle {

std::string read_bounded_text(const std::string& path, const std::string& what,
                              const std::string& kind, uint64_t max_bytes) {
  const SourceLocation where{path, 0, 0, "", ""};
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0)
    throw InputError(where, "cannot read " + what + ": " + std::strerror(errno));
  if (!S_ISREG(info.st_mode)) throw InputError(where, "is not a regular file; " + kind);
  if (static_cast<uint64_t>(info.st_size) > max_bytes)
    throw InputError(where, "is " + std::to_string(info.st_size) + " bytes; " + what +
                                " is at most " + std::to_string(max_bytes >> 20) + " MiB");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(where, "cannot read " + what + ": " + std::strerror(errno));
  // Read into one string of the size stat gave (a stream's copies held a 60 MB drawing three
  // times); a file still being written is refused, not read past its bound.
  std::string text(static_cast<size_t>(info.st_size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(in.gcount()));
  if (in.get() != std::char_traits<char>::eof())
    throw InputError(where, "grew while it was read; read " + what + " once it is saved");
  return text;
}

std::string read_own_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

}  // namespace curdle
