#include "layout/triangulation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <deque>
#include <utility>
#include <vector>

namespace curdle {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
  int nesting = -1;  // how many constraint rings lie between the face and the outside
};
using Vb = CGAL::Triangulation_vertex_base_2<Kernel>;
using Fbb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>;
using Fb = CGAL::Constrained_triangulation_face_base_2<Kernel, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

}  // namespace

std::vector<std::array<std::array<double, 2>, 3>> triangulate(const std::vector<Ring>& rings) {
  // All corners and edges at once: CGAL sorts the points along a space-filling curve before it
  // inserts them, where edge by edge each insertion walked from the last (a perforated sheet of
  // 8,000 round openings spent seconds here).
  std::vector<Kernel::Point_2> points;
  std::vector<std::pair<size_t, size_t>> edges;
  for (const Ring& ring : rings) {
    const size_t first = points.size();
    for (const auto& v : ring) points.emplace_back(v[0], v[1]);
    for (size_t i = 0; i < ring.size(); ++i)
      edges.emplace_back(first + i, first + (i + 1) % ring.size());
  }
  Cdt cdt;
  cdt.insert_constraints(points.begin(), points.end(), edges.begin(), edges.end());
  // Flood the faces from the outside; crossing a constrained edge adds one level.
  std::deque<std::pair<Cdt::Face_handle, int>> queue{{cdt.infinite_face(), 0}};
  while (!queue.empty()) {
    auto [face, level] = queue.front();
    queue.pop_front();
    if (face->info().nesting != -1) continue;
    face->info().nesting = level;
    for (int i = 0; i < 3; ++i) {
      const Cdt::Face_handle next = face->neighbor(i);
      if (next->info().nesting != -1) continue;
      if (cdt.is_constrained(Cdt::Edge(face, i)))
        queue.emplace_back(next, level + 1);
      else
        queue.emplace_front(next, level);
    }
  }
  std::vector<std::array<std::array<double, 2>, 3>> out;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info().nesting % 2 != 1) continue;
    std::array<std::array<double, 2>, 3> t;
    for (int i = 0; i < 3; ++i) t[i] = {f->vertex(i)->point().x(), f->vertex(i)->point().y()};
    out.push_back(t);  // CGAL's faces are counter-clockwise
  }
  return out;
}

}  // namespace curdle
