#include "contact_geometry.hpp"

namespace grainlab {

ContactGeometry collidePolygonWall(const Polygon& poly, const Vec2& x, double c, double s, const Wall& wall) {
  ManifoldPoints m;
  for (int k = 0; k < poly.count; ++k) {
    const Vec2& v = poly.vertices[k];
    const Vec2 w(x.x() + c * v.x() - s * v.y(), x.y() + s * v.x() + c * v.y());
    const double depth = -(w - wall.point).dot(wall.normal);
    if (depth <= 0) continue;
    // Keep the two deepest vertices.
    const Vec2 mid = w + wall.normal * (0.5 * depth);
    if (m.count < 2) {
      m.points[m.count] = mid;
      m.depths[m.count++] = depth;
    } else {
      const int shallower = m.depths[0] < m.depths[1] ? 0 : 1;
      if (depth > m.depths[shallower]) {
        m.points[shallower] = mid;
        m.depths[shallower] = depth;
      }
    }
  }
  return reduceManifold(-wall.normal, m);
}

}  // namespace grainlab
