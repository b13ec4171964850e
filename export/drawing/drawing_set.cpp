#include "export/drawing/drawing_set.h"

#include <cairo-pdf.h>
#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include "curdle/error.h"
#include "curdle/stop.h"
#include "export/drawing/course_marks.h"
#include "export/drawing/installer_drawing.h"
#include "export/drawing/layout_png.h"
#include "export/drawing/page_buffer.h"
#include "export/drawing/setting_out_plan.h"
#include "export/drawing/sheet_drawing.h"
#include "layout/arc_setting_out.h"
#include "layout/curved_facade.h"
#include "layout/installer_sheets.h"
#include "layout/laying_pattern.h"
#include "layout/legend.h"
#include "layout/piece.h"
#include "layout/piece_rows.h"
#include "layout/title_block.h"

namespace curdle {
namespace {

using namespace sheet_drawing;

// Sheet 1: the layout, legend with counts, quantities per value, scale bar, title block.
void draw_overview(cairo_t* cr, const Layout& layout, const OverviewSheet& s, size_t total,
                   const PreviewImage* raster) {
  const double w = s.landscape ? s.paper.long_side : s.paper.short_side;
  const double h = s.landscape ? s.paper.short_side : s.paper.long_side;
  frame(cr, w, h);
  const auto area = drawing_area(s.paper, s.landscape);
  View v;
  v.window = {0, 0, layout.width, layout.height};
  v.scale = s.scale;
  v.left = kLeftMargin + (area[0] - layout.width / s.scale) / 2;
  v.top = kMargin + (area[1] - layout.height / s.scale) / 2;
  if (raster) {
    // The picture's own pixels, on whole pixels of the sheet.
    const double ppm = layout.drawing.dpi / 25.4;
    v.left = std::round(v.left * ppm) / ppm, v.top = std::round(v.top * ppm) / ppm;
    const size_t pixels = static_cast<size_t>(raster->width) * raster->height;
    const PageBuffer buffer(pixels * 4);
    uint32_t* argb = buffer.as<uint32_t>();
    for (size_t i = 0; i < pixels; ++i)
      argb[i] = 0xff000000u | uint32_t{raster->rgb[3 * i]} << 16 |
                uint32_t{raster->rgb[3 * i + 1]} << 8 | raster->rgb[3 * i + 2];
    cairo_surface_t* image =
        cairo_image_surface_create_for_data(buffer.as<unsigned char>(), CAIRO_FORMAT_RGB24,
                                            raster->width, raster->height, raster->width * 4);
    cairo_save(cr);
    cairo_translate(cr, v.left, v.top);
    cairo_scale(cr, 1 / ppm, 1 / ppm);
    cairo_set_source_surface(cr, image, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
    cairo_paint(cr);
    cairo_restore(cr);
    cairo_surface_destroy(image);
  } else {
    draw_pieces(cr, layout, v, false);
  }
  draw_zones(cr, layout, v, true);
  colour(cr, kInk);
  v.rect(cr, v.window);
  cairo_set_line_width(cr, 0.25);
  cairo_stroke(cr);
  start_corner(cr, layout, v);
  draw_facades(cr, layout, v);
  const double strip = h - kMargin - kTitleStrip;
  setting_out(cr, layout, v, strip - 1);
  // A curved wall's setting-out plan where the sheet has more room, above the elevation or
  // below it (clear of its setting-out marks and caption, and of the scale bar).
  const double above = v.top - kMargin - 12, below_y = v.top + layout.height / s.scale + 18;
  const double below = strip - 12 - below_y;
  if (std::max(above, below) > 30)
    draw_setting_out_plan(cr, layout, kLeftMargin + 2, above >= below ? kMargin + 3 : below_y,
                          area[0] - 4, std::max(above, below));

  // Legend: up to 8 rows a column, 62 mm a column, from the strip's left.
  size_t shown = 0;
  const double room = w - kMargin - title_width(w) - kLeftMargin - 6;
  const size_t columns = room >= 200 ? 2 : 1;
  const double column_w = room / static_cast<double>(columns);
  for (const auto& [parts, line] : sheet_legend(layout)) {
    if (shown == 8 * columns) break;
    const double x = kLeftMargin + 3 + column_w * static_cast<double>(shown / 8);
    const double y = strip + 4 + 5.6 * static_cast<double>(shown % 8);
    ++shown;
    for (size_t i = 0; i < parts.size(); ++i) {
      colour(cr, parts[i]);
      cairo_rectangle(cr, x + 8.0 * static_cast<double>(i) / static_cast<double>(parts.size()), y,
                      8.0 / static_cast<double>(parts.size()), 4);
      cairo_fill(cr);
    }
    colour(cr, kInk);
    if (!parts.empty()) box(cr, x, y, 8, 4, 0.2);  // a line of a breakdown has no swatch
    key_text(cr, x + 10, y + 3.4, line, column_w - 12, 2);
  }
  scale_bar(cr, w - kMargin - title_width(w), strip - 6, s.scale, title_width(w) - 20);
  const std::string segment = segment_text(layout);
  title_block(cr, layout, title_lines(layout), w, h,
              segment.empty() ? "the whole layout" : "a segment: " + segment, s.scale, 1, total,
              s.paper.name);
}

// The key of one installer's sheet: a swatch as drawn, the material and how many of it the
// sheet holds, in columns of six lines from (x, y) within `width`.
void draw_sheet_key(cairo_t* cr, const SheetContents& held, bool coursed, double x, double y,
                    double width) {
  text(cr, x, y, "key: on this sheet", 2, Align::left, false, true);
  const size_t columns = std::max<size_t>(1, static_cast<size_t>(width / 60));
  const double column_w = width / static_cast<double>(columns);
  size_t shown = 0;
  for (const auto& [what, line] : held.key) {
    if (shown == 6 * columns) {
      text(cr, x, y + 4.5 * 7, fmt::format("and {} more", held.key.size() - shown), 2);
      break;
    }
    const double lx = x + column_w * static_cast<double>(shown / 6);
    const double ly = y + 2.5 + 4.5 * static_cast<double>(shown % 6);
    ++shown;
    for (size_t i = 0; i < line.swatch.size(); ++i) {
      colour(cr, line.swatch[i], coursed ? 1 : kFaintAlpha);  // as the sheet draws the pieces
      const double part = 6.0 / static_cast<double>(line.swatch.size());
      cairo_rectangle(cr, lx + part * static_cast<double>(i), ly, part, 3);
      cairo_fill(cr);
    }
    if (coursed) {
      cairo_save(cr);
      cairo_rectangle(cr, lx, ly, 6, 3);
      cairo_clip(cr);
      hatch(cr, line.value, line.swatch.front(), lx, ly, lx + 6, ly + 3);
      cairo_restore(cr);
    }
    colour(cr, kInk);
    box(cr, lx, ly, 6, 3, 0.2);
    const std::string label = fmt::format("{}: {}", what.first, line.count);
    key_text(cr, lx + 8, ly + 2.6, label, column_w - 10, 1.8);
  }
}

// Labels: inside their piece, or beside it on white with a leader that the plan keeps clear of
// every other label and leader; leaders first, under the labels' white.
void draw_labels(cairo_t* cr, const InstallerPlan& plan, const View& v,
                 const std::vector<uint32_t>& on_sheet) {
  colour(cr, kInk);
  cairo_set_line_width(cr, 0.15);
  for (const uint32_t i : on_sheet) {
    const InstallerLabel& l = plan.labels[i];
    if (l.inside) continue;
    const auto [ax, ay] = leader_end(l);
    cairo_move_to(cr, v.x(l.anchor[0]), v.y(l.anchor[1]));
    cairo_line_to(cr, v.x(ax), v.y(ay));
    cairo_stroke(cr);
    cairo_new_path(cr);
    cairo_arc(cr, v.x(l.anchor[0]), v.y(l.anchor[1]), kLeaderDotMm, 0, 2 * M_PI);
    cairo_fill(cr);
  }
  for (const uint32_t i : on_sheet) {
    const InstallerLabel& l = plan.labels[i];
    if (!l.inside) {
      colour(cr, Rgb{255, 255, 255});
      v.rect(cr, l.box);
      cairo_fill_preserve(cr);
      colour(cr, kInk);
      cairo_set_line_width(cr, 0.1);
      cairo_stroke(cr);
    }
    colour(cr, kInk);
    const double cx = v.x(l.box.x + l.box.w / 2), cy = v.y(l.box.y + l.box.h / 2);
    // Two lines a label's height apart, the first above (read up the page: left).
    const std::vector<std::string> lines = label_lines(l);
    for (size_t k = 0; k < lines.size(); ++k) {
      const double step = (static_cast<double>(k) - (static_cast<double>(lines.size()) - 1) / 2) *
                          label_height_mm(plan.text_mm);
      // On the piece, the ID stands on a halo: a zone's outline or a joint under it would
      // strike it through.
      if (l.rotated)
        text_on_halo(cr, cx + step + plan.text_mm / 2, cy, lines[k], plan.text_mm, Align::centre,
                     true);
      else
        text_on_halo(cr, cx, cy + step + plan.text_mm / 2, lines[k], plan.text_mm, Align::centre);
    }
  }
}

// Match lines: the edges shared with the next sheets, each named in its caption's box.
void draw_match_lines(cairo_t* cr, const InstallerPlan& plan, const View& v, size_t index) {
  const InstallerSheet& sheet = plan.sheets[index];
  const double wl = v.x(sheet.window.x), wr = v.x(sheet.window.right());
  const double wt = v.y(sheet.window.top()), wb = v.y(sheet.window.y);
  const double dashes[] = {6, 1.5, 1, 1.5};
  for (const MatchCaption& c : plan.captions) {
    if (c.sheet != index) continue;
    const InstallerSheet& other = plan.sheets[c.other];
    colour(cr, kBlue);
    cairo_set_line_width(cr, 0.5);
    cairo_set_dash(cr, dashes, 4, 0);
    if (other.column != sheet.column) {
      const double x = other.column < sheet.column ? wl : wr;
      cairo_move_to(cr, x, wt), cairo_line_to(cr, x, wb);
    } else {
      const double y = other.row < sheet.row ? wb : wt;
      cairo_move_to(cr, wl, y), cairo_line_to(cr, wr, y);
    }
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    const std::string t = match_caption_text(c);
    colour(cr, Rgb{255, 255, 255});  // on white, over whatever is laid there
    v.rect(cr, c.box);
    cairo_fill(cr);
    colour(cr, kBlue);
    const double cx = v.x(c.box.x + c.box.w / 2), cy = v.y(c.box.y + c.box.h / 2);
    if (c.vertical)
      text(cr, cx + kMatchCaptionMm / 2, cy, t, kMatchCaptionMm, Align::centre, true);
    else
      text(cr, cx, cy + kMatchCaptionMm / 2, t, kMatchCaptionMm, Align::centre);
  }
}

// The key plan in the title strip: the whole grid of sheets, this one filled, and the start
// corner's dot.
void draw_key_plan(cairo_t* cr, const Layout& layout, const InstallerPlan& plan, size_t index,
                   double kx, double ky, double kw, double kh) {
  const double gw = plan.sheets.back().window.right() - plan.sheets.front().window.x;
  const double gh = plan.sheets.back().window.top() - plan.sheets.front().window.y;
  const double k = std::min(kw / gw, kh / gh);
  auto kxf = [&](double x) { return kx + (x - plan.sheets.front().window.x) * k; };
  auto kyf = [&](double y) { return ky + kh - (y - plan.sheets.front().window.y) * k; };
  colour(cr, kInk);
  text(cr, kx, ky - 3, "key plan", 2);
  colour(cr, Rgb{220, 220, 220});
  cairo_rectangle(cr, kxf(0), kyf(layout.height), layout.width * k, layout.height * k);
  cairo_fill(cr);
  for (size_t i = 0; i < plan.sheets.size(); ++i) {
    const Rect& r = plan.sheets[i].window;
    if (i == index) {
      colour(cr, kBlue, 0.45);
      cairo_rectangle(cr, kxf(r.x), kyf(r.top()), r.w * k, r.h * k);
      cairo_fill(cr);
    }
    colour(cr, kInk);
    box(cr, kxf(r.x), kyf(r.top()), r.w * k, r.h * k, 0.15);
    if (r.w * k > 6 && r.h * k > 3)
      text(cr, kxf(r.x + r.w / 2), kyf(r.y + r.h / 2) + 1,
           std::to_string(installer_sheet_number(i)), 1.8, Align::centre);
  }
  const double ox = from_right(layout.origin) ? layout.width : 0;
  const double oy = from_top(layout.origin) ? layout.height : 0;
  colour(cr, kRed);
  cairo_new_path(cr);
  cairo_arc(cr, kxf(ox), kyf(oy), 0.8, 0, 2 * M_PI);
  cairo_fill(cr);
}

// Where the sheet sits from the datum, and the openings and zones that show on it, as the
// x and y of their edges (mm from the datum, as sheet 1 sets out), so that a setter-out can
// start from any sheet.
std::vector<std::string> sheet_setting_out(const Layout& layout, const Rect& window) {
  const Rect on = clip(window, layout.width, layout.height);
  std::vector<std::string> lines{
      fmt::format("from the datum (0, 0): x {:.0f} to {:.0f}, y {:.0f} to {:.0f}", on.x, on.right(),
                  on.y, on.top())};
  std::vector<std::pair<std::string, Rect>> shown;
  for (size_t i = 0; i < layout.openings_given; ++i)
    shown.emplace_back(layout.envelope && i < layout.envelope->opening_names.size()
                           ? layout.envelope->opening_names[i]
                           : fmt::format("opening {}", i + 1),
                       layout.openings[i]);
  for (const ZoneCount& z : layout.zones) {
    if (z.polygon.empty() || !z.contour.empty()) continue;  // arcs: by centre and radius, below
    Rect r{z.polygon[0][0], z.polygon[0][1], 0, 0};
    for (const auto& p : z.polygon) {
      const double x0 = std::min(r.x, p[0]), y0 = std::min(r.y, p[1]);
      const double x1 = std::max(r.right(), p[0]), y1 = std::max(r.top(), p[1]);
      r = {x0, y0, x1 - x0, y1 - y0};
    }
    shown.emplace_back(z.name.empty() ? std::string("zone") : z.name, r);
  }
  size_t more = 0;
  for (const auto& [name, r] : shown) {
    if (!overlaps(r, on)) continue;
    if (lines.size() >= 4) {
      ++more;
      continue;
    }
    lines.push_back(fmt::format("{}: x {} to {}, y {} to {}", name, drawing_mm(r.x),
                                drawing_mm(r.right()), drawing_mm(r.y), drawing_mm(r.top())));
  }
  // Arcs that run over the sheet, by their centre, radius and ends.
  for (const SetOutArc& a : arcs_to_set_out(layout)) {
    Contour one{{a.arc.from[0], a.arc.from[1], bulge_of_sweep(a.arc.sweep)},
                {a.arc.to[0], a.arc.to[1], 0}};
    if (a.circle) one = {{a.arc.from[0], a.arc.from[1], 1}, {a.arc.to[0], a.arc.to[1], 1}};
    const Rect extent = contour_bounds(one);
    if (!overlaps(Rect{extent.x - 1, extent.y - 1, extent.w + 2, extent.h + 2}, on)) continue;
    if (lines.size() >= 4) {
      ++more;
      continue;
    }
    lines.push_back(a.line);
  }
  if (more) lines.back() += fmt::format("; {} more on sheet 1", more);
  return lines;
}

// An installer's sheet: the part of the layout in its window with every ID, match lines, row
// and column numbers, a key plan and the start corner.
void draw_installer_sheet(cairo_t* cr, const Layout& layout, const InstallerDrawing& set,
                          size_t index, size_t total) {
  const InstallerPlan& plan = set.plan;
  const double w = plan.landscape ? plan.paper.long_side : plan.paper.short_side;
  const double h = plan.landscape ? plan.paper.short_side : plan.paper.long_side;
  frame(cr, w, h);
  const InstallerSheet& sheet = plan.sheets[index];
  View v;
  v.window = sheet.window;
  v.scale = plan.scale;
  v.left = kLeftMargin + 14;  // the row-number strip (installer_sheets.cpp)
  v.top = kMargin;
  v.elements = &set.elements_on[index];
  cairo_save(cr);
  v.rect(cr, sheet.window);  // the window is the viewport, or less where it ends at a joint
  cairo_clip(cr);
  draw_pieces(cr, layout, v, !plan.coursed);
  if (plan.coursed) draw_hatches(cr, layout, v);
  draw_zones(cr, layout, v, false);
  colour(cr, Rgb{85, 85, 85});
  cairo_set_line_width(cr, 0.1);
  for (const uint32_t i : set.pieces_on[index]) {
    const InstallerPiece& p = plan.pieces[i];
    if (p.outline) {
      ring_paths(cr, p.outline->rings, v);
      cairo_stroke(cr);
      continue;
    }
    for (const Rect& r : p.parts) v.rect(cr, r), cairo_stroke(cr);
  }
  draw_boundary(cr, layout, v);
  draw_labels(cr, plan, v, set.labels_on[index]);
  cairo_restore(cr);
  draw_facades(cr, layout, v);
  // The start corner, when it is on this sheet.
  const double sx = from_right(layout.origin) ? layout.width : 0;
  const double sy = from_top(layout.origin) ? layout.height : 0;
  if (sx >= sheet.window.x && sx <= sheet.window.right() && sy >= sheet.window.y &&
      sy <= sheet.window.top())
    start_corner(cr, layout, v);
  colour(cr, kInk);
  box(cr, v.left, v.top, plan.viewport[0], plan.viewport[1], 0.35);

  draw_match_lines(cr, plan, v, index);
  // A pattern's rows are not straight courses: its units are found by their IDs' rows.
  if (layout.kind->laid_in_courses() && layout.pattern == LayingPattern::grid)
    draw_course_numbers(cr, plan, set.extents, v);
  if (plan.coursed && layout.pattern == LayingPattern::grid) {
    draw_gauge_rod(cr, layout, set.extents, v, plan.viewport);
    draw_dimension_chain(cr, layout, v, plan.viewport);
  }
  const double strip = h - kMargin - kTitleStrip;
  const double kx = kLeftMargin + 4, kw = 70;
  draw_key_plan(cr, layout, plan, index, kx, strip + 8, kw, kTitleStrip - 12);

  // What the sheet holds, and the title block.
  const SheetContents& held = set.contents[index];
  const size_t pieces = held.pieces;
  colour(cr, kInk);
  const double info_x = kx + kw + 8;
  // The key takes the right part of the strip beside the title block, the notes the left.
  const double room = w - kMargin - title_width(w) - 4 - info_x;
  const double key_w = std::min(room * 0.38, 110.0), info_w = room - key_w - 6;
  draw_sheet_key(cr, set.contents[index], plan.coursed, info_x + info_w + 4, strip + 6, key_w);
  const std::string unit = legend_unit(layout);
  const std::string holds =
      pieces == 0 ? "no pieces"
      : layout.fabrication
          ? fmt::format("{} sheet{}", pieces, pieces == 1 ? "" : "s")
          : fmt::format("{}: {} {} to {}, columns {} to {}", legend_count(layout, pieces),
                        plan.coursed ? "courses" : "rows", held.row0, held.row1, held.column0,
                        held.column1);
  std::vector<std::string> info = {
      fmt::format("installer's sheet {} of {}: grid row {}, column {}",
                  installer_sheet_number(index), total, sheet.row + 1, sheet.column + 1),
      holds,
      plan.coursed
          ? fmt::format("each {} in its key's colour and hatch", unit)
          : fmt::format("IDs {:.1f} mm high; a label off its piece points to it", plan.text_mm)};
  if (plan.coursed && layout.pattern == LayingPattern::grid)
    info.push_back("courses left, columns below; gauge rod in mm right");
  else if (plan.coursed)
    info.push_back(fmt::format("laid {}: each unit as drawn", pattern_name(layout.pattern)));
  // A curved façade on the sheet: its radius, centre, each unit's chord and the joints' taper.
  for (const CurvedFacade& c : curved_facades(layout))
    if (c.frame->start < sheet.window.right() && c.frame->start + c.frame->length > sheet.window.x)
      info.insert(info.end(), c.brief.begin(), c.brief.end());
  if (held.backing)
    info.push_back(fmt::format("behind them, {}: {}", layout.backing()->material, held.backing));
  for (std::string& line : sheet_setting_out(layout, sheet.window)) info.push_back(std::move(line));
  if (plan.unplaced)
    info.push_back(fmt::format("{} labels found no room: use a larger sheet", plan.unplaced));
  // Up to eight lines above the scale bar, at the foot of the strip.
  info.resize(std::min<size_t>(info.size(), 8));
  info = fit_lines(cr, info, info_w, 2);
  for (size_t i = 0; i < info.size(); ++i)
    text(cr, info_x, strip + 8 + 4.2 * static_cast<double>(i), info[i], 2, Align::left, false,
         i == 0);
  scale_bar(cr, info_x, strip + 43, plan.scale, std::min(90.0, info_w));
  title_block(cr, layout, set.title, w, h, "installer's sheet", plan.scale,
              installer_sheet_number(index), total, plan.paper.name);
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::ostream*>(closure)->write(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

OverviewSheet overview_sheet(const Layout& layout) {
  OverviewSheet s;
  s.paper = paper_sheet(layout.drawing.paper).value_or(*paper_sheet("A3"));
  s.scale = drawing_scale(layout);
  for (const char* name : {"A4", "A3", "A2", "A1", "A0"}) {
    const PaperSheet p = *paper_sheet(name);
    if (p.long_side < s.paper.long_side) continue;
    for (const bool landscape : {layout.width >= layout.height, layout.width < layout.height}) {
      const auto area = drawing_area(p, landscape);
      if (layout.width / s.scale <= area[0] + 1e-6 && layout.height / s.scale <= area[1] + 1e-6) {
        s.paper = p, s.landscape = landscape;
        return s;
      }
    }
  }
  throw InputError(SourceLocation{"", 0, 0, "layout.scale", ""},
                   fmt::format("at 1 : {:g} the layout is {:.0f} x {:.0f} mm, larger than an A0 "
                               "sheet's drawing area; give a larger scale, or leave layout.scale "
                               "out to have one picked",
                               s.scale, layout.width / s.scale, layout.height / s.scale));
}

void write_layout_pdf(std::ostream& out, const Layout& layout, const InstallerPlan& plan) {
  const OverviewSheet overview = overview_sheet(layout);
  const size_t total = 1 + plan.sheets.size();
  auto size = [](const PaperSheet& p, bool landscape) {
    return std::array<double, 2>{(landscape ? p.long_side : p.short_side) * kPointsPerMm,
                                 (landscape ? p.short_side : p.long_side) * kPointsPerMm};
  };
  const auto first = size(overview.paper, overview.landscape);
  cairo_surface_t* surface = cairo_pdf_surface_create_for_stream(append, &out, first[0], first[1]);
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE,
                                 (layout.source.recipe + " - drawing set").c_str());
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "curdle");
  // A fixed date instead of the clock's: the same run writes the same bytes.
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATE_DATE, "2000-01-01T00:00:00Z");
  cairo_t* cr = cairo_create(surface);
  cairo_scale(cr, kPointsPerMm, kPointsPerMm);
  draw_overview(cr, layout, overview, total, nullptr);
  cairo_show_page(cr);
  const InstallerDrawing set = installer_set(layout, plan);
  const auto next = size(plan.paper, plan.landscape);
  cairo_pdf_surface_set_size(surface, next[0], next[1]);
  for (size_t i = 0; i < plan.sheets.size(); ++i) {
    draw_installer_sheet(cr, layout, set, i, total);
    cairo_show_page(cr);
  }
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const cairo_status_t status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    throw InputError(std::string("cannot write layout.pdf: ") + cairo_status_to_string(status) +
                     " (is the disk full?)");
}

namespace {

// Sheet 1 drawn by cairo into pixels of its own (17 MB at A3 and 150 dpi, zeroed as cairo's
// are): 0x00RRGGBB words, `stride` bytes a row.
struct SheetPixels {
  PageBuffer pixels{0};
  int width = 0, height = 0, stride = 0;

  // Row y as RGB bytes.
  void row(int y, uint8_t* rgb) const {
    const unsigned char* data = pixels.as<unsigned char>() + static_cast<size_t>(y) * stride;
    for (int x = 0; x < width; ++x, rgb += 3) {
      uint32_t p;
      std::memcpy(&p, data + 4 * x, 4);
      rgb[0] = p >> 16 & 255, rgb[1] = p >> 8 & 255, rgb[2] = p & 255;
    }
  }
};

SheetPixels draw_sheet_one(const Layout& layout, const InstallerPlan& plan) {
  const OverviewSheet overview = overview_sheet(layout);
  const PreviewImage raster = render_layout(layout);
  const double ppm = layout.drawing.dpi / 25.4;
  SheetPixels sheet;
  sheet.width = static_cast<int>(std::lround(
      (overview.landscape ? overview.paper.long_side : overview.paper.short_side) * ppm));
  sheet.height = static_cast<int>(std::lround(
      (overview.landscape ? overview.paper.short_side : overview.paper.long_side) * ppm));
  sheet.stride = cairo_format_stride_for_width(CAIRO_FORMAT_RGB24, sheet.width);
  sheet.pixels = PageBuffer(static_cast<size_t>(sheet.stride) * static_cast<size_t>(sheet.height));
  cairo_surface_t* surface =
      cairo_image_surface_create_for_data(sheet.pixels.as<unsigned char>(), CAIRO_FORMAT_RGB24,
                                          sheet.width, sheet.height, sheet.stride);
  cairo_t* cr = cairo_create(surface);
  cairo_scale(cr, ppm, ppm);
  const size_t total = 1 + plan.sheets.size();  // "sheet 1 of n"
  draw_overview(cr, layout, overview, total, &raster);
  cairo_destroy(cr);
  cairo_surface_flush(surface);
  cairo_surface_destroy(surface);
  return sheet;
}

}  // namespace

PreviewImage render_layout_sheet(const Layout& layout, const InstallerPlan& plan) {
  const SheetPixels sheet = draw_sheet_one(layout, plan);
  PreviewImage image;
  image.width = sheet.width, image.height = sheet.height;
  image.rgb.resize(static_cast<size_t>(sheet.width) * sheet.height * 3);
  for (int y = 0; y < sheet.height; ++y)
    sheet.row(y, &image.rgb[static_cast<size_t>(y) * sheet.width * 3]);
  return image;
}

std::string layout_sheet_png(const Layout& layout, const InstallerPlan& plan) {
  const SheetPixels sheet = draw_sheet_one(layout, plan);
  return encode_png(
      sheet.width, sheet.height, [&](int y, uint8_t* rgb) { sheet.row(y, rgb); },
      layout.drawing.dpi);
}

uint64_t layout_sheet_pixels(const LayoutSpec& spec) {
  const PaperSheet paper = paper_sheet(spec.drawing.paper).value_or(*paper_sheet("A3"));
  const double ppm = spec.drawing.dpi / 25.4;
  // The sheet itself: A0 at most, when a given scale makes it grow.
  const double sheet =
      std::max(paper.long_side * paper.short_side, 841.0 * 1189.0 * (spec.drawing.scale > 0));
  return static_cast<uint64_t>(sheet * ppm * ppm);
}

}  // namespace curdle
