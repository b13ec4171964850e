#include "building/coursing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "curdle/error.h"

namespace curdle {
namespace {

constexpr double kEps = 1e-6;
constexpr double kBend = 15;  // degrees: a smaller turn is laid round, not turned

// A piece fixed before the runs are filled: a corner's unit or a stopped end's half unit.
struct Fixed {
  double from = 0, to = 0;
  UnitRole role = UnitRole::corner;
  int corner = -1;
};

// The units of a run [s, e] (both at a unit's face, joints outside): whole units from the
// ends, the cut in the middle. Appends a note once for a sliver no arrangement avoids.
void fill_run(double s, double e, int64_t course, double l, double j, double min_cut,
              std::vector<CourseUnit>& out, bool& sliver) {
  const double room = e - s;
  if (room < kEps) return;
  const int64_t whole = static_cast<int64_t>(std::floor((room + j) / (l + j) + kEps));
  const double left = room - (static_cast<double>(whole) * (l + j) - j);
  std::vector<double> lengths(static_cast<size_t>(whole), l);
  if (left > kEps) {
    const double cut = left - j;  // one more unit, with its joint
    if (cut >= min_cut - kEps) {
      lengths.insert(lengths.begin() + whole / 2, cut);
    } else if (whole >= 1) {  // one unit less, and two cut halves between
      const double half = (l + cut) / 2;
      lengths.erase(lengths.begin());
      lengths.insert(lengths.begin() + (whole - 1) / 2, 2, half);
    } else {
      lengths.push_back(room);
      sliver = true;
    }
  }
  double at = s;
  for (double len : lengths) {
    CourseUnit u;
    u.course = course;
    u.from = at;
    u.to = at + len;
    u.role = std::fabs(len - l) < kEps ? UnitRole::stretcher : UnitRole::closer;
    out.push_back(u);
    at += len + j;
  }
}

// The header's reach along the face at an outer corner: the unit's depth, or at a corner
// sharper than a right angle as far as its back's mitre, d tan(turn / 2), so that the special
// cut to the angle closes behind its face.
double header_reach(double turn, double d) {
  constexpr double kPi = 3.14159265358979323846;
  return turn > 90 ? d * std::tan(turn / 2 * kPi / 180) : d;
}

// How far the unit turning the corner at the end of façade k reaches back along it and on
// along the next in course r: at an outer corner a stretcher and a header, changing sides
// course by course (stack bond: every course alike); at an inner corner the unit running
// through shows length - depth on one side only.
std::pair<double, double> corner_unit(const SurfaceFrame& f, size_t k, int64_t r, double l,
                                      double d, bool stack) {
  const bool first = stack || ((r + static_cast<int64_t>(k)) % 2 == 0);
  const double h = header_reach(f.turn_at_end, d);
  if (f.turn_at_end > 0) return first ? std::pair{l, h} : std::pair{h, l};
  return first ? std::pair{l - d, 0.0} : std::pair{0.0, l - d};
}

}  // namespace

void check_corner_room(const Envelope& env, const LayoutSpec& spec) {
  const double l = spec.module_w, j = spec.joint, d = env.depth;
  const size_t n = env.facades.size();
  auto turns = [&](size_t k) {
    const SurfaceFrame& f = env.facades[k];
    return !f.last_of_path && std::string(corner_kind(f.turn_at_end)) != "bend";
  };
  for (size_t k = 0; k < n; ++k) {
    const SurfaceFrame& f = env.facades[k];
    if (turns(k) && f.turn_at_end > 0 && header_reach(f.turn_at_end, d) > l) {
      SourceLocation where;
      where.key = env.closed ? "plan" : "path";
      throw InputError(
          where, fmt::format("the corner at the end of façade {} is {:.1f}°, too sharp for a "
                             "{:g} mm unit {:g} mm deep to turn: its back meets the next face's "
                             "{:.0f} mm from the arris; corners of at least {:.1f}° can be laid",
                             f.name, 180 - f.turn_at_end, l, d, header_reach(f.turn_at_end, d),
                             180 - 2 * std::atan(l / d) * 180 / 3.14159265358979323846));
    }
    const size_t before = (k + n - 1) % n;
    const bool from_corner = (env.closed || k > 0) && turns(before);
    for (int64_t r = 0; r < 2; ++r) {  // the two courses of the bond
      double need = 0;
      if (from_corner) need += corner_unit(env.facades[before], before, r, l, d, false).second;
      if (turns(k)) need += corner_unit(f, k, r, l, d, false).first;
      if (need > 0) need += j;
      if (f.length + 1e-6 < need) {
        SourceLocation where;
        where.key = env.closed ? "plan" : "path";
        throw InputError(where,
                         fmt::format("façade {} is {:g} mm long, too short for the units that "
                                     "turn its corners: at least {:g} mm ({:g} mm units, {:g} mm "
                                     "deep, {:g} mm joints)",
                                     f.name, f.length, need, l, d, j));
      }
    }
  }
}

const char* corner_kind(double turn) {
  if (std::fabs(turn) < kBend) return "bend";
  return turn > 0 ? "outer" : "inner";
}

Coursing course_envelope(const Envelope& env, const LayoutSpec& spec, bool stack) {
  Coursing c;
  const double l = spec.module_w, j = spec.joint, d = env.depth;
  const double min_cut = spec.min_cut[0] > 0 ? spec.min_cut[0] : l / 3;
  const double L = env.length;
  const size_t n = env.facades.size();
  bool sliver = false;
  for (int64_t r = 0; r < env.courses; ++r) {
    std::vector<Fixed> fixed;
    for (size_t k = 0; k < n; ++k) {
      const SurfaceFrame& f = env.facades[k];
      if (f.last_of_path || std::string(corner_kind(f.turn_at_end)) == "bend") continue;
      const double at = f.start + f.length;
      const auto [a, b] = corner_unit(f, k, r, l, d, stack);
      fixed.push_back({at - a, at + b, UnitRole::corner, static_cast<int>(k)});
    }
    if (!env.closed && !stack && r % 2 == 1) {  // stopped ends: a half unit on alternate courses
      fixed.insert(fixed.begin(), {0, d, UnitRole::end, -1});
      fixed.push_back({L - d, L, UnitRole::end, -1});
    }
    // The runs between fixed pieces, round the strip; a closed envelope's last corner wraps.
    std::vector<CourseUnit> course;
    const bool wraps = env.closed && !fixed.empty() && fixed.back().corner == int(n) - 1;
    double s = wraps ? fixed.back().to - L + j : 0;
    for (const Fixed& p : fixed) {
      fill_run(s, p.from - (p.from > kEps ? j : 0), r, l, j, min_cut, course, sliver);
      course.push_back({r, p.from, p.to, p.role, p.corner});
      s = p.to + j;
    }
    if (!wraps) fill_run(s, L, r, l, j, min_cut, course, sliver);
    std::sort(course.begin(), course.end(),
              [](const CourseUnit& x, const CourseUnit& y) { return x.from < y.from; });
    c.units.insert(c.units.end(), course.begin(), course.end());
  }
  for (size_t k = 0; k < n; ++k) {
    const SurfaceFrame& f = env.facades[k];
    if (f.last_of_path) continue;
    const SurfaceFrame& next = env.facades[(k + 1) % n];
    const std::string kind = corner_kind(f.turn_at_end);
    const double angle = 180 - std::fabs(f.turn_at_end);
    if (kind == "bend") {
      c.notes.push_back(fmt::format("{} to {}: a bend of {:.1f}°, laid round without a corner unit",
                                    f.name, next.name, std::fabs(f.turn_at_end)));
      continue;
    }
    const bool square = std::fabs(angle - 90) < 0.5;
    c.notes.push_back(fmt::format(
        "{} to {}: an {} corner of {:.1f}°{}, {}", f.name, next.name, kind, angle,
        square ? "" : " (special units cut or made to this angle)",
        kind == "outer" ? (stack ? "a stretcher each course on the first face and a header on the "
                                   "next"
                                 : "stretcher and header changing sides course by course (quoin)")
                        : "one face's unit running through behind the other's, changing sides "
                          "course by course"));
  }
  if (sliver)
    c.notes.push_back(
        fmt::format("a run between corners is shorter than the narrowest cut "
                    "({:g} mm) and is laid as one cut piece",
                    min_cut));
  return c;
}

}  // namespace curdle
