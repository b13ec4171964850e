#include "layout/triangulation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <deque>

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
  Cdt cdt;
  for (const Ring& ring : rings)
    for (size_t i = 0; i < ring.size(); ++i) {
      const auto& a = ring[i];
      const auto& b = ring[(i + 1) % ring.size()];
      cdt.insert_constraint(Kernel::Point_2(a[0], a[1]), Kernel::Point_2(b[0], b[1]));
    }
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
