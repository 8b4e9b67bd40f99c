#include "grainlab/particle_store.hpp"

#include <cmath>
#include <stdexcept>

namespace grainlab {

int ParticleStore::add(const ParticleSpec& spec, const Material& material) {
  const int index = size();
  Vec2 centre = spec.position;
  double area = 0, polar = 0, bounding = 0;
  int polygonIndex = -1;
  if (spec.shape == ShapeKind::Disc) {
    if (!(spec.radius > 0) || !std::isfinite(spec.radius)) {
      throw std::invalid_argument("disc radius must be positive and finite");
    }
    area = discArea(spec.radius);
    polar = 0.5 * area * spec.radius * spec.radius;
    bounding = spec.radius;
  } else if (spec.shape == ShapeKind::Clump) {
    Vec2 centroid;
    Clump clump = makeClump(spec.members, &centroid);
    // Members are relative to `position` in the body frame turned by `angle`, as vertices are.
    centre = spec.position + rotate(centroid, spec.angle);
    area = clump.area;
    polar = clump.polarMoment;
    bounding = clump.circumradius;
    polygonIndex = static_cast<int>(clumps.size());
    clumps.push_back(std::move(clump));
  } else {
    Vec2 centroid;
    Polygon poly = makePolygon(spec.vertices, &centroid);
    // Vertices are relative to `position` in the body frame turned by `angle`.
    centre = spec.position + rotate(centroid, spec.angle);
    area = poly.area;
    polar = poly.polarMoment;
    bounding = poly.circumradius;
    polygonIndex = static_cast<int>(polygons.size());
    polygons.push_back(poly);
  }
  const double m = material.density * area;
  const double i = material.density * polar;
  const bool dynamic = spec.motion == Motion::Dynamic;
  const bool moving = spec.motion != Motion::Fixed;

  position.push_back(centre);
  angle.push_back(spec.angle);
  cosAngle.push_back(std::cos(spec.angle));
  sinAngle.push_back(std::sin(spec.angle));
  velocity.push_back(moving ? spec.velocity : Vec2::Zero());
  spin.push_back(moving ? spec.spin : 0.0);
  force.push_back(Vec2::Zero());
  torque.push_back(0.0);
  invMass.push_back(dynamic ? 1.0 / m : 0.0);
  invInertia.push_back(dynamic ? 1.0 / i : 0.0);
  mass.push_back(m);
  inertia.push_back(i);
  boundingRadius.push_back(bounding);
  shape.push_back(spec.shape);
  motion.push_back(spec.motion);
  boundary.push_back(spec.boundary ? 1 : 0);
  shapeIndex.push_back(polygonIndex);
  return index;
}

int ParticleStore::addWall(const Wall& wall) {
  Wall w = wall;
  const double len = w.normal.norm();
  if (!(len > 0) || !std::isfinite(len)) throw std::invalid_argument("wall normal must be non-zero");
  w.normal /= len;
  walls.push_back(w);
  return static_cast<int>(walls.size()) - 1;
}

double ParticleStore::area(int k) const {
  switch (shape[k]) {
    case ShapeKind::Disc: return discArea(boundingRadius[k]);
    case ShapeKind::Polygon: return polygonOf(k).area;
    case ShapeKind::Clump: return clumpOf(k).area;
  }
  return 0;
}

}  // namespace grainlab
