#include "export/schedules/punching.h"

#include <fmt/format.h>

#include <map>
#include <set>

#include "io/csv_field.h"
#include "layout/wkt.h"

namespace curdle {

void write_punching_csv(std::ostream& out, const Layout& layout) {
  std::set<std::string> tools;  // every punch any sheet uses, in order of name
  for (const FabricationSheet& s : layout.sheets())
    for (const auto& [tool, hits] : s.tools) tools.insert(tool);
  out << kUtf8Mark
      << "sheet_id,material,thickness_mm,stock_width_mm,stock_height_mm,sheet_area_m2,"
         "offcut_m2,open_share";
  for (const std::string& t : tools) out << "," << (t == "outline" ? "outline_cuts" : "hits_" + t);
  out << ",facade,blank_width_mm,blank_height_mm,bend_radius_mm\r\n";
  const double stock = layout.fabrication->stock[0] * layout.fabrication->stock[1];
  double area = 0, offcut = 0, open = 0;
  std::map<std::string, uint64_t> total;
  auto row = [&](const std::string& id, double sheet_area, double sheet_offcut, double share,
                 const std::map<std::string, uint64_t>& hits, const FabricationSheet* sheet) {
    out << fmt::format("{},{},{},{},{},{:.6f},{:.6f},{:.4f}", csv_field(id),
                       csv_field(layout.fabrication->material), mm_text(layout.thickness),
                       mm_text(layout.fabrication->stock[0]), mm_text(layout.fabrication->stock[1]),
                       sheet_area / 1e6, sheet_offcut / 1e6, share);
    for (const std::string& t : tools) out << "," << (hits.count(t) ? hits.at(t) : 0);
    if (sheet)  // the blank the punch takes: a rolled sheet's developed at mid-thickness
      out << fmt::format(",{},{:.2f},{:.2f},{}", csv_field(sheet->facade),
                         sheet->area.w * sheet->developed, sheet->area.h,
                         sheet->bend_radius > 0 ? fmt::format("{:.1f}", sheet->bend_radius) : "");
    else
      out << ",,,,";
    out << "\r\n";
  };
  for (const FabricationSheet& s : layout.sheets()) {
    const std::map<std::string, uint64_t> hits(s.tools.begin(), s.tools.end());
    row(s.id, s.surface, stock - s.surface, s.open_area, hits, &s);
    area += s.surface, offcut += stock - s.surface, open += s.open_area * s.surface;
    for (const auto& [t, n] : hits) total[t] += n;
  }
  row("total", area, offcut, area > 0 ? open / area : 0, total, nullptr);
}

}  // namespace curdle
