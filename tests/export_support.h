// Helpers the exporters' tests share.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "curdle/curdling.h"
#include "curdle/error.h"
#include "curdle/overlay.h"
#include "curdle/palette.h"
#include "curdle/report.h"
#include "export/report/cells_csv.h"
#include "export/report/preview_png.h"
#include "export/report/report_json.h"
#include "export/report/report_table.h"
#include "io/atomic_file.h"
#include "io/cells_csv_reader.h"
#include "test_support.h"

namespace fs = std::filesystem;

namespace curdle {

using test::design;

inline fs::path temp_dir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("curdle-test-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    EXPECT_TRUE(!line.empty() && line.back() == '\r') << "RFC 4180 rows end in CRLF";
    line.pop_back();
    std::vector<std::string> fields;
    std::stringstream ss(line);
    std::string f;
    while (std::getline(ss, f, ',')) fields.push_back(f);
    rows.push_back(fields);
  }
  return rows;
}

// RFC 4180 rows: CRLF line ends, quoted fields may hold commas; every row as wide as the header.
inline std::vector<std::vector<std::string>> strict_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows(1);
  std::string cell;
  bool quoted = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"')
        cell += '"', ++i;
      else if (c == '"')
        quoted = false;
      else
        cell += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      rows.back().push_back(cell), cell.clear();
    } else if (c == '\r') {
      EXPECT_EQ(text[i + 1], '\n') << "CR without LF";
      rows.back().push_back(cell), cell.clear();
      rows.emplace_back();
      ++i;
    } else {
      EXPECT_NE(c, '\n') << "bare LF";
      cell += c;
    }
  }
  EXPECT_TRUE(rows.back().empty() && cell.empty()) << "the last row must end in CRLF";
  rows.pop_back();
  for (size_t r = 1; r < rows.size(); ++r)
    EXPECT_EQ(rows[r].size(), rows[0].size()) << "ragged row " << r;
  return rows;
}

}  // namespace curdle
