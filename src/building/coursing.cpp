#include "building/coursing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "building/run_fill.h"
#include "curdle/error.h"

namespace curdle {
namespace {

constexpr double kEps = 1e-6;
constexpr double kBend = 15;  // degrees: a smaller turn is laid round, not turned

// The header's reach along the face at an outer corner: the unit's depth, or at a corner
// sharper than a right angle as far as its back's mitre, d tan(turn / 2), so that the special
// cut to the angle closes behind its face.
double header_reach(double turn, double d) {
  constexpr double kPi = 3.14159265358979323846;
  return turn > 90 ? d * std::tan(turn / 2 * kPi / 180) : d;
}

bool turns(const SurfaceFrame& f) {
  return !f.last_of_path && std::string(corner_kind(f.turn_at_end)) != "bend";
}

// Each face's place in the bond: the corners turned before it (a bend turns none).
std::vector<int> bond_parity(const Envelope& env) {
  std::vector<int> out;
  int count = 0;
  for (const SurfaceFrame& f : env.facades) out.push_back(count), count += turns(f);
  return out;
}

// How far the unit turning the corner at the end of façade k reaches back along it and on
// along the next in course r: at an outer corner a stretcher and a header, changing sides
// course by course (stack bond: every course alike); at an inner corner the unit running
// through shows length - depth on one side only.
std::pair<double, double> corner_unit(const SurfaceFrame& f, int parity, int64_t r, double l,
                                      double d, bool stack) {
  const bool first = stack || ((r + parity) % 2 == 0);
  const double h = header_reach(f.turn_at_end, d);
  if (f.turn_at_end > 0) return first ? std::pair{l, h} : std::pair{h, l};
  return first ? std::pair{l - d, 0.0} : std::pair{0.0, l - d};
}

}  // namespace

void check_corner_room(const Envelope& env, const LayoutSpec& spec) {
  const double l = spec.module_w, j = spec.joint, d = env.depth;
  const size_t n = env.facades.size();
  const std::vector<int> parity = bond_parity(env);
  for (size_t k = 0; k < n; ++k) {
    const SurfaceFrame& f = env.facades[k];
    if (turns(f) && f.turn_at_end > 0 && header_reach(f.turn_at_end, d) > l) {
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
    const bool from_corner = (env.closed || k > 0) && turns(env.facades[before]);
    for (int64_t r = 0; r < 2; ++r) {  // the two courses of the bond
      double need = 0;
      if (from_corner)
        need += corner_unit(env.facades[before], parity[before], r, l, d, false).second;
      if (turns(f)) need += corner_unit(f, parity[k], r, l, d, false).first;
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

namespace {

// Lays one course: the pieces fixed at the corners (and stopped ends), then each run between.
class CourseLayer {
 public:
  CourseLayer(const Envelope& env, const LayoutSpec& spec, CourseBond bond, bool& sliver)
      : env_(env),
        bond_(bond),
        l_(spec.module_w),
        j_(spec.joint),
        d_(env.depth),
        parity_(bond_parity(env)) {
    fill_.l = l_, fill_.j = j_, fill_.sliver = &sliver;
    fill_.min_cut = spec.min_cut[0] > 0 ? spec.min_cut[0] : l_ / 3;
  }

  std::vector<CourseUnit> lay(int64_t r) {
    std::vector<CourseUnit> course;
    fill_.course = r, fill_.out = &course;
    const double L = env_.length;
    const size_t n = env_.facades.size();
    std::vector<Fixed> fixed;
    for (size_t k = 0; k < n; ++k) {
      const SurfaceFrame& f = env_.facades[k];
      if (!turns(f)) continue;
      const double at = f.start + f.length;
      const auto [a, b] = corner_unit(f, parity_[k], r, l_, d_, bond_ == CourseBond::stack);
      fixed.push_back({at - a, at + b, UnitRole::corner, static_cast<int>(k)});
    }
    if (!env_.closed && bond_ == CourseBond::stretcher && r % 2 == 1) {  // half units
      fixed.insert(fixed.begin(), {0, d_, UnitRole::end, -1});
      fixed.push_back({L - d_, L, UnitRole::end, -1});
    }
    // The runs between fixed pieces, round the strip; a closed envelope's last corner wraps.
    const bool wraps = env_.closed && !fixed.empty() && fixed.back().corner == int(n) - 1;
    double s = wraps ? fixed.back().to - L + j_ : 0;
    double reach = wraps ? fixed.back().to - L : -1;  // on the run's face; -1: a stopped end
    for (const Fixed& p : fixed) {
      const double at = p.corner < 0 ? 0 : facade_end(p.corner);
      run(s, p.from - (p.from > kEps ? j_ : 0), reach, p.role == UnitRole::end ? -1 : at - p.from);
      course.push_back({r, p.from, p.to, p.role, p.corner});
      s = p.to + j_;
      reach = p.corner < 0 ? -1 : p.to - at;
    }
    if (!wraps) run(s, L, reach, -1);
    std::sort(course.begin(), course.end(),
              [](const CourseUnit& x, const CourseUnit& y) { return x.from < y.from; });
    return course;
  }

 private:
  struct Fixed {
    double from = 0, to = 0;
    UnitRole role = UnitRole::corner;
    int corner = -1;
  };

  double facade_end(int k) const {
    const SurfaceFrame& f = env_.facades[static_cast<size_t>(k)];
    return f.start + f.length;
  }

  // The run [s, e]; `before` and `after`: how far the fixed pieces at its ends reach along its
  // face (-1 at a stopped end).
  void run(double s, double e, double before, double after) {
    const int64_t r = fill_.course;
    switch (bond_) {
      case CourseBond::stack:
      case CourseBond::stretcher:
        return fill_whole_from_ends(fill_, s, e);
      case CourseBond::third:
      case CourseBond::quarter: {
        const double share = bond_ == CourseBond::third ? 1.0 / 3 : 0.25;
        const double moved = static_cast<double>(r) * share;
        return fill_on_phase(fill_, s, e, (moved - std::floor(moved)) * (l_ + j_));
      }
      default: {
        const SurfaceFrame* f = frame_at(env_.facades, std::min(s + kEps, env_.length));
        const bool headers = (r + parity_[f ? f->index : 0]) % 2 == 1;
        return fill_in_order(fill_, s, e, order(headers, before), order(headers, after));
      }
    }
  }

  // English or Flemish bond's order from a run's end, after a piece that reaches `reach` along
  // the face (-1: a stopped end): a queen closer beside a header at the quoin, so that the
  // courses lap by a quarter.
  BondOrder order(bool header_course, double reach) const {
    const BondPiece S{l_, UnitRole::stretcher, 0}, H{d_, UnitRole::header, l_};
    const BondPiece Q{queen_closer(d_, j_), UnitRole::closer, l_};
    if (bond_ == CourseBond::english) {
      if (!header_course) return {{}, {S}};
      return reach < 0 ? BondOrder{{H, Q}, {H}} : BondOrder{{Q}, {H}};
    }
    if (reach < 0) return fill_.course % 2 == 0 ? BondOrder{{}, {S, H}} : BondOrder{{H, Q}, {S, H}};
    return reach >= l_ - d_ - kEps ? BondOrder{{}, {H, S}} : BondOrder{{Q}, {S, H}};
  }

  const Envelope& env_;
  CourseBond bond_;
  double l_, j_, d_;
  RunFill fill_;
  std::vector<int> parity_;
};

// How English or Flemish bond is laid round the building, for the report.
std::string bond_note(const Envelope& env, const LayoutSpec& spec, CourseBond bond) {
  std::string note = fmt::format(
      "{} bond: {}; a queen closer of {:g} mm beside the header at each corner, so that the "
      "courses lap by a quarter; headers {:g} mm on the face and {:g} mm into the wall",
      bond == CourseBond::english ? "English" : "Flemish",
      bond == CourseBond::english
          ? "courses of stretchers and of headers by turns, a face's header course meeting the "
            "next face's stretcher course at each corner"
          : "headers and stretchers by turns in every course",
      queen_closer(env.depth, spec.joint), env.depth, spec.module_w);
  int corners = 0;
  for (const SurfaceFrame& f : env.facades) corners += turns(f);
  if (bond == CourseBond::english && env.closed && corners % 2 == 1)
    note += fmt::format(
        "; with {} corners round the building, the closing corner joins two courses of the "
        "same kind",
        corners);
  return note;
}

}  // namespace

Coursing course_envelope(const Envelope& env, const LayoutSpec& spec, CourseBond bond) {
  Coursing c;
  c.bond = bond;
  bool sliver = false;
  CourseLayer layer(env, spec, bond, sliver);
  for (int64_t r = 0; r < env.courses; ++r) {
    const std::vector<CourseUnit> course = layer.lay(r);
    c.units.insert(c.units.end(), course.begin(), course.end());
  }
  const double min_cut = spec.min_cut[0] > 0 ? spec.min_cut[0] : spec.module_w / 3;
  const bool stack = bond == CourseBond::stack;
  const size_t n = env.facades.size();
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
  if (bond == CourseBond::english || bond == CourseBond::flemish)
    c.notes.push_back(bond_note(env, spec, bond));
  if (sliver)
    c.notes.push_back(
        fmt::format("a run between corners is shorter than the narrowest cut "
                    "({:g} mm) and is laid as one cut piece",
                    min_cut));
  return c;
}

}  // namespace curdle
