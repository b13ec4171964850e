// dxflib's ASCII writer, buffered. DL_WriterA flushes its file after every real number: fig. 7's
// 2 MB layout.dxf took 85,000 write calls, most of its 0.22 s. This writer is a DL_WriterA for
// every dxflib call, and writes the same bytes through one buffer.
#pragma once

#include <dxflib/dl_writer_ascii.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace curdle {

class BufferedDxfWriter : public DL_WriterA {
 public:
  explicit BufferedDxfWriter(const std::filesystem::path& path);
  bool failed() const { return !out_.is_open() || out_.fail(); }
  // Writes out the buffer and closes the file; false when a byte could not be written.
  bool finish();

  // As DL_WriterA writes them: a group code right-aligned to three columns, then its value,
  // each on a line; a real in fixed notation with 16 decimals, trailing zeros cut to one.
  void dxfReal(int gc, double value) const override;
  void dxfInt(int gc, int value) const override;
  void dxfHex(int gc, int value) const override;
  void dxfString(int gc, const char* value) const override;
  void dxfString(int gc, const std::string& value) const override;

 private:
  void group(int gc) const;
  std::vector<char> buffer_;
  mutable std::ofstream out_;
};

}  // namespace curdle
