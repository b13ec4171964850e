#include "export/schedules/schedule.h"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "curdle/markov.h"
#include "curdle/palette.h"
#include "io/csv_field.h"
#include "layout/piece.h"
#include "layout/union.h"
#include "layout/wkt.h"
#include "layout/zone.h"

namespace curdle {
namespace {
double stock_area(const Element& e) { return e.stock_w * e.stock_h; }

// A plain curd's column is 0 or 1; a Markov curd's holds its state's name, "dead" where none.
struct CurdColumns {
  std::vector<CurdGroup> groups;
  std::vector<std::vector<std::string>> states;  // per group, ",name" per state code

  explicit CurdColumns(const std::vector<CurdSpec>& curds) : groups(curd_groups(curds)) {
    for (const CurdGroup& g : groups) {
      states.emplace_back();
      if (g.chain)
        for (uint32_t s = 0; s < (1u << g.planes); ++s) {
          std::string cell(1, ',');
          cell += csv_field(g.chain->state_name(s));
          states.back().push_back(std::move(cell));
        }
    }
  }
  void append(std::string& buffer, uint32_t value) const {
    for (size_t g = 0; g < groups.size(); ++g) {
      const uint32_t state = groups[g].state(value);
      if (groups[g].chain)
        buffer += states[g][state];
      else
        buffer += state ? ",1" : ",0";
    }
  }
};

void append_whole(std::string& out, int64_t v) {
  std::array<char, 24> digits;
  out.append(digits.data(), std::to_chars(digits.data(), digits.data() + digits.size(), v).ptr);
}

void append_optional_mm(std::string& out, const std::optional<double>& v) {
  if (v) append_mm_text(out, *v);
}

// A row written in place, field by field: a string made for every number was most of the
// file's time.
void append_row(std::string& b, const ScheduleRow& r, const CurdColumns& curds) {
  b += r.id;
  b += ',';
  b += r.lot;
  b += ',';
  if (r.level) append_whole(b, *r.level);
  for (const int64_t v : {r.row, r.column}) {
    b += ',';
    append_whole(b, v);
  }
  for (const double v : {r.x, r.y, r.z, r.width, r.height}) {
    b += ',';
    append_mm_text(b, v);
  }
  b += ',';
  append_optional_mm(b, r.depth);
  fmt::format_to(std::back_inserter(b), FMT_COMPILE(",{:.6f},"), area_m2(r.area));
  append_optional_mm(b, r.stock_width);
  b += ',';
  append_optional_mm(b, r.stock_height);
  b += ',';
  append_whole(b, r.value);
  curds.append(b, r.value);
  b += ',';
  append_csv_field(b, r.element_type);
  b += ',';
  b += r.colour;
  b += ',';
  append_csv_field(b, r.material);
  b += r.cut ? ",1," : ",0,";
  std::string wkt;
  append_outlines_wkt(wkt, r.outlines);
  append_csv_field(b, wkt);
  for (const auto& v : {r.opening_x, r.opening_y, r.opening_diameter}) {
    b += ',';
    append_optional_mm(b, v);
  }
  if (r.strip_x) {
    b += ',';
    append_csv_field(b, r.facade);
    b += ',';
    append_mm_text(b, *r.strip_x);
    b += ',';
    append_optional_mm(b, r.strip_y);
  }
  b += "\r\n";
}

}  // namespace

void write_schedule_csv(std::ostream& out, const Layout& layout) {
  const Provenance& design = layout.source;
  std::string header = kUtf8Mark;
  header +=
      "element_id,lot,level,row,column,x_mm,y_mm,z_mm,width_mm,height_mm,depth_mm,area_m2,"
      "stock_width_mm,stock_height_mm,value";
  const CurdColumns columns(design.curds);
  for (const CurdGroup& g : columns.groups) {
    header += ',';
    header += csv_field(design.curds[g.first].name);
  }
  header +=
      ",element_type,colour,material,cut,shape_wkt,opening_x_mm,opening_y_mm,"
      "opening_diameter_mm";
  if (layout.envelope) header += ",facade,strip_x_mm,strip_y_mm";
  header += "\r\n";
  out << header;
  std::string buffer;
  buffer.reserve(1 << 20);
  for (size_t i = 0; i < layout.elements.size(); ++i) {
    append_row(buffer, schedule_row(layout, i), columns);
    if (buffer.size() > (1 << 20) - 4096) {
      out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      buffer.clear();
    }
  }
  out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
}

namespace {

// One order line: pieces of one type, material, colour and stock size; openings of one size
// (a tool's diameter), whichever curds cut them.
struct OrderLine {
  std::map<uint32_t, bool> values;
  std::set<std::string> materials, colours;  // an opening line's, joined
  uint64_t count = 0, whole = 0, cut = 0;
  double laid_area = 0, stock_area = 0;
};
using OrderKey = std::tuple<std::string, std::string, std::string, std::string>;

// A park's surface (gravel, a path, the ground): laid to the cells' shapes and bought by area,
// one line per material, not as pieces of odd "stock sizes" sold in packs.
constexpr const char* kByArea = "by area";
bool bought_by_area(const Element& e) { return e.form == ElementForm::object && !e.stands; }

OrderKey order_key(const Layout& layout, const Element& e) {
  if (bought_by_area(e))
    return {element_type_of(layout, e), piece_material(layout, e),
            hex_colour(piece_colour(layout, e)), kByArea};
  if (e.form == ElementForm::opening)  // punched or cut by size: one line per diameter
    return {element_type_of(layout, e), "", "", stock_size_of(layout, e)};
  return {element_type_of(layout, e), piece_material(layout, e),
          hex_colour(piece_colour(layout, e)), stock_size_of(layout, e)};
}

// A one-brick wall's backing unit behind a face unit that does not run through: the face
// unit's size, in the backing's material, unseen (no colour or value).
void add_backing(std::map<OrderKey, OrderLine>& lines, const Layout& layout, const Element& e) {
  if (!needs_backing(layout, e)) return;
  const std::string& material = layout.backing()->material;
  OrderLine& l = lines[{layout.element_type + ", backing", material, "", stock_size_of(layout, e)}];
  l.materials.insert(material);
  ++l.count;
  (e.cut ? l.cut : l.whole) += 1;
  l.laid_area += std::round(e.area());
  l.stock_area += stock_area(e);
}

void add_to(OrderLine& l, const Layout& layout, const Element& e) {
  l.materials.insert(piece_material(layout, e));
  l.colours.insert(hex_colour(piece_colour(layout, e)));
  ++l.count;
  (e.cut ? l.cut : l.whole) += 1;
  // schedule.csv prints each piece's area to the mm² (m² to 6 places): the sum of those, so that
  // its column adds up to this one exactly.
  l.laid_area += std::round(e.area());
  l.stock_area += bought_by_area(e) ? std::round(e.area()) : stock_area(e);
  l.values[e.value] = true;
}

std::string value_list(const OrderLine& l) {
  std::string s;
  for (const auto& [v, _] : l.values) {
    if (!s.empty()) s += ' ';
    s += std::to_string(v);
  }
  return s;
}

// The columns quantities.csv and lots.csv share: element_type, material, colour, size_mm,
// values, count, whole, cut, laid_area_m2, stock_area_m2.
std::string order_fields(const OrderKey& key, const OrderLine& l) {
  auto joined = [](const std::set<std::string>& items) {
    std::string s;
    for (const std::string& item : items) s += (s.empty() ? "" : " + ") + item;
    return s;
  };
  const std::string material = std::get<1>(key).empty() ? joined(l.materials) : std::get<1>(key);
  const std::string colour = std::get<2>(key).empty() ? joined(l.colours) : std::get<2>(key);
  return fmt::format("{},{},{},{},{},{},{},{},{:.6f},{:.6f}", csv_field(std::get<0>(key)),
                     csv_field(material), csv_field(colour), csv_field(std::get<3>(key)),
                     value_list(l), l.count, l.whole, l.cut, l.laid_area / 1e6, l.stock_area / 1e6);
}

}  // namespace

void write_quantities_csv(std::ostream& out, const Layout& layout) {
  const OrderingKeys& spec = layout.ordering;
  std::map<OrderKey, OrderLine> lines;
  for (const Element& e : layout.elements) {
    add_to(lines[order_key(layout, e)], layout, e);
    add_backing(lines, layout, e);
  }
  out << kUtf8Mark
      << "element_type,material,colour,size_mm,values,count,whole,cut,laid_area_m2,"
         "stock_area_m2,spare,count_with_spare,area_to_buy_m2,pack_size,packs\r\n";
  for (const auto& [key, l] : lines) {
    if (std::get<1>(key).empty()) {  // openings: nothing is bought, no spare and no packs
      out << fmt::format("{},0,{},0.000000,,\r\n", order_fields(key, l), l.count);
      continue;
    }
    if (std::get<3>(key) == kByArea) {  // an area and its spare, no pieces or packs to buy
      out << fmt::format("{},{},{},{:.6f},,\r\n", order_fields(key, l), spec.spare, l.count,
                         l.laid_area * (1 + spec.spare) / 1e6);
      continue;
    }
    // Every piece, whole or cut, takes one stock element: offcuts are not reused.
    const auto with_spare = static_cast<uint64_t>(std::ceil(l.count * (1 + spec.spare) - 1e-9));
    // Specials are made to order and bought by the piece, not in packs.
    const auto pack =
        std::get<0>(key).find(", special for") != std::string::npos ? int64_t{1} : spec.pack;
    const auto packs = (with_spare + pack - 1) / pack;
    const double per_piece = l.count ? l.stock_area / static_cast<double>(l.count) : 0;
    out << fmt::format("{},{},{},{:.6f},{},{}\r\n", order_fields(key, l), spec.spare, with_spare,
                       per_piece * static_cast<double>(with_spare) / 1e6, pack, packs);
  }
}

void write_lots_csv(std::ostream& out, const Layout& layout) {
  std::map<std::string, std::map<OrderKey, OrderLine>> lots;
  std::vector<std::string> order;  // lots in laying order
  for (size_t i = 0; i < layout.elements.size(); ++i) {
    const Element& e = layout.elements[i];
    std::string lot = lot_text(layout, e, i);
    if (e.form == ElementForm::block)
      lot = "level " + std::to_string(e.cell_z - layout.view.origin[2]);
    if (!lots.count(lot)) order.push_back(lot);
    add_to(lots[lot][order_key(layout, e)], layout, e);
    add_backing(lots[lot], layout, e);
  }
  out << kUtf8Mark
      << "lot,element_type,material,colour,size_mm,values,count,whole,cut,laid_area_m2,"
         "stock_area_m2\r\n";
  for (const std::string& lot : order)
    for (const auto& [key, l] : lots[lot])
      out << csv_field(lot) << ',' << order_fields(key, l) << "\r\n";
}

}  // namespace curdle
