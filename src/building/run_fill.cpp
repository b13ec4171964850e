#include "building/run_fill.h"

#include <algorithm>
#include <cmath>

namespace curdle {
namespace {

constexpr double kEps = 1e-6;

void put(const RunFill& f, double from, double width, UnitRole role, double depth = 0) {
  CourseUnit u;
  u.course = f.course;
  u.from = from;
  u.to = from + width;
  u.role = role;
  u.depth = depth;
  f.out->push_back(u);
}

// The gap [from, to] between the pieces already laid (their joints outside it): one cut, or
// two halves where it is longer than a unit (a short cut taken with its whole neighbour).
void cut_gap(const RunFill& f, double from, double to, double depth = 0) {
  const double gap = to - from;
  if (gap <= -f.j + kJointTolerance) return;      // filled, a joint a little wider at most
  if (std::fabs(gap - f.l) <= kJointTolerance) {  // a whole unit, its joints taking it up
    put(f, from + (gap - f.l) / 2, f.l, UnitRole::stretcher, depth);
    return;
  }
  if (gap > f.l + kEps) {
    const double half = (gap - f.j) / 2;
    put(f, from, half, UnitRole::closer, depth);
    put(f, from + half + f.j, half, UnitRole::closer, depth);
    return;
  }
  if (gap < f.min_cut - kEps) *f.sliver = true;
  put(f, from, std::max(gap, 0.0), UnitRole::closer, depth);
}

}  // namespace

void fill_whole_from_ends(const RunFill& f, double s, double e) {
  const double room = e - s, l = f.l, j = f.j;
  if (room < kEps) return;
  // Within what its joints take up of whole units: those units, the difference in their joints.
  const double nearest = std::round((room + j) / (l + j));
  if (nearest >= 1 &&
      std::fabs(room + j - nearest * (l + j)) <= joint_play(static_cast<int64_t>(nearest) - 1, j)) {
    const auto n = static_cast<int64_t>(nearest);
    const double joint = n > 1 ? (room - nearest * l) / (nearest - 1) : 0;
    double at = n > 1 ? s : s + (room - l) / 2;
    for (int64_t k = 0; k < n; ++k, at += l + joint) put(f, at, l, UnitRole::stretcher);
    return;
  }
  const int64_t whole = static_cast<int64_t>(std::floor((room + j) / (l + j) + kEps));
  const double left = room - (static_cast<double>(whole) * (l + j) - j);
  std::vector<double> lengths(static_cast<size_t>(whole), l);
  if (left > kEps) {
    const double cut = left - j;  // one more unit, with its joint
    if (cut >= f.min_cut - kEps) {
      lengths.insert(lengths.begin() + whole / 2, cut);
    } else if (whole >= 1) {  // one unit less, and two cut halves between
      const double half = (l + cut) / 2;
      lengths.erase(lengths.begin());
      lengths.insert(lengths.begin() + (whole - 1) / 2, 2, half);
    } else {
      lengths.push_back(room);
      *f.sliver = true;
    }
  }
  double at = s;
  for (double len : lengths) {
    put(f, at, len, std::fabs(len - l) < kEps ? UnitRole::stretcher : UnitRole::closer);
    at += len + j;
  }
}

void fill_on_phase(const RunFill& f, double s, double e, double phase) {
  const double pitch = f.l + f.j;
  // The whole units that lie on the phase within the run, with room for a closer or none.
  double first = phase + std::ceil((s - phase) / pitch - kEps) * pitch;
  double last = phase + std::floor((e - f.l - phase) / pitch + kEps) * pitch;  // its start
  if (last < first - kEps) return fill_whole_from_ends(f, s, e);
  // A lead closer too narrow is taken with the first unit, and a trailing one with the last.
  if (first - s > kEps && first - f.j - s < f.min_cut - kEps) first += pitch;
  if (e - (last + f.l) > kEps && e - last - f.l - f.j < f.min_cut - kEps) last -= pitch;
  if (last < first - kEps) return fill_whole_from_ends(f, s, e);
  if (first - s > kEps) cut_gap(f, s, first - f.j);
  for (double at = first; at <= last + kEps; at += pitch) put(f, at, f.l, UnitRole::stretcher);
  if (e - (last + f.l) > kEps) cut_gap(f, last + f.l + f.j, e);
}

void fill_in_order(const RunFill& f, double s, double e, const BondOrder& from_start,
                   const BondOrder& from_end) {
  if (e - s < kEps) return;
  struct End {
    const BondOrder& order;
    size_t next = 0;
    std::vector<BondPiece> laid;
    const BondPiece& peek() const {
      return next < order.first.size()
                 ? order.first[next]
                 : order.cycle[(next - order.first.size()) % order.cycle.size()];
    }
  };
  End head{from_start}, tail{from_end};
  double lo = s, hi = e;  // where the next piece from each end starts, and ends
  bool from_head = true;
  for (int misses = 0; misses < 2; from_head = !from_head) {
    End& end = from_head ? head : tail;
    const BondPiece p = end.peek();
    if (p.width > hi - lo + kEps) {
      ++misses;
      continue;
    }
    misses = 0;
    end.laid.push_back(p);
    ++end.next;
    if (from_head)
      lo += p.width + f.j;
    else
      hi -= p.width + f.j;
  }
  // Pieces are taken back from the ends until the middle's cut is wide enough (two halves
  // where it is then longer than a unit).
  double depth = 0;
  while (hi - lo > -f.j + kEps && hi - lo < f.min_cut - kEps &&
         head.laid.size() + tail.laid.size() > 1) {
    End& end = head.laid.size() >= tail.laid.size() ? head : tail;
    const BondPiece p = end.laid.back();
    end.laid.pop_back();
    (&end == &head ? lo : hi) += (&end == &head ? -1 : 1) * (p.width + f.j);
    depth = p.depth;
  }
  double at = s;
  for (const BondPiece& p : head.laid) put(f, at, p.width, p.role, p.depth), at += p.width + f.j;
  at = e;
  for (const BondPiece& p : tail.laid)
    at -= p.width, put(f, at, p.width, p.role, p.depth), at -= f.j;
  cut_gap(f, lo, hi, depth);
}

}  // namespace curdle
