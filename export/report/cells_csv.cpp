#include "export/report/cells_csv.h"

#include <charconv>
#include <string>

#include "curdle/markov.h"
#include "curdle/overlay.h"
#include "curdle/stop.h"
#include "io/csv_field.h"

namespace curdle {

void write_cells_csv(std::ostream& out, const Design& design, const CurdField& field,
                     const Box& view, const std::function<void(double)>& progress) {
  const int E = design.lattice.dimension;
  static const char* axes[] = {"x", "y", "z"};
  std::string header = kUtf8Mark;
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on chains of string +.
  for (int d = 0; d < E; ++d) {
    if (d) header += ',';
    header += axes[d];
  }
  header += ",value";
  // A plain curd's column is 0 or 1; a Markov curd's holds its state's name, "dead" where none.
  const std::vector<CurdGroup> groups = curd_groups(design.curds);
  std::vector<std::vector<std::string>> state_cells(groups.size());
  for (size_t g = 0; g < groups.size(); ++g) {
    header += ',';
    header += csv_field(design.curds[groups[g].first].name);
    if (groups[g].chain)
      for (uint32_t s = 0; s < (1u << groups[g].planes); ++s) {
        std::string cell(1, ',');
        cell += csv_field(groups[g].chain->state_name(s));
        state_cells[g].push_back(std::move(cell));
      }
  }
  out << header << "\r\n";

  std::string buffer;
  buffer.reserve(1 << 20);
  char num[24];
  auto put = [&](int64_t v) {
    auto [p, ec] = std::to_chars(num, num + sizeof num, v);
    buffer.append(num, p);
  };
  scan_rows(
      field, view,
      [&](int64_t y, int64_t z, std::span<const uint16_t> row) {
        stop_point();  // a row at a time: 2048^2 cells of 16 curds is seconds of text
        for (size_t i = 0; i < row.size(); ++i) {
          put(view.origin[0] + static_cast<int64_t>(i));
          if (E >= 2) buffer += ',', put(y);
          if (E >= 3) buffer += ',', put(z);
          buffer += ',';
          put(row[i]);
          for (size_t g = 0; g < groups.size(); ++g) {
            const uint32_t state = groups[g].state(row[i]);
            if (groups[g].chain)
              buffer += state_cells[g][state];
            else
              buffer += state ? ",1" : ",0";
          }
          buffer += "\r\n";
        }
        if (buffer.size() > (1 << 20) - 4096) {
          out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
          buffer.clear();
        }
      },
      progress);
  out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
}

}  // namespace curdle
