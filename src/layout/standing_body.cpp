#include "layout/standing_body.h"

namespace curdle {

double body_height(const Layout& layout, const Element& e) {
  if (e.form == ElementForm::block) return layout.level_height;
  if (e.circle) return kTrunkHeight + e.circle->d;
  return e.stands ? kStandingHeight : layout.thickness;
}

double body_volume(const Element& e) {
  if (!e.circle || e.form == ElementForm::block) return -1;
  const double pi = 3.14159265358979323846, r = e.circle->d / 2, trunk = kTrunkWidth / 2;
  return (pi * trunk * trunk * kTrunkHeight + pi * r * r * e.circle->d) / 1e9;
}

}  // namespace curdle
