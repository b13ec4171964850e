// dxflib's ASCII writer, buffered. DL_WriterA flushes its file after every real number: fig. 7's
// 2 MB layout.dxf took 85,000 write calls, most of its 0.22 s. This writer is a DL_WriterA for
// every dxflib call, and writes the same bytes through a buffer of its own (through a stream's,
// five inserts a group were a third of the pavilion's layout.dxf).
#pragma once

#include <dxflib/dl_writer_ascii.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace curdle {

class BufferedDxfWriter : public DL_WriterA {
 public:
  explicit BufferedDxfWriter(const std::filesystem::path& path);
  ~BufferedDxfWriter() override;  // writes out what is buffered, as a stream would
  BufferedDxfWriter(const BufferedDxfWriter&) = delete;
  BufferedDxfWriter& operator=(const BufferedDxfWriter&) = delete;
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
  static constexpr size_t kFlushAt = 1 << 20;
  void group(int gc) const;
  void line(std::string_view text) const;  // the text and its line's end
  void flush() const;
  mutable std::string buffer_;
  mutable std::ofstream out_;
};

}  // namespace curdle
