#pragma once
// The particle shapes of the paper's assemblies (Fig. 4) and the measures of a convex
// polygon the generator needs.
#include <span>
#include <vector>

#include "grainlab/clump.hpp"
#include "grainlab/math.hpp"

namespace grainlab::specimen {

/// Vertices (m) of the convex polygon inscribed in the ellipse whose long axis `longAxis`
/// (m) lies along +x and whose short axis is longAxis / aspectRatio: `vertexCount` (3..8)
/// vertices at equal parametric angles 2πk/n starting on the +x end, counter-clockwise.
/// The polygon is the affine image of a regular n-gon, so its centroid is the origin, it
/// is symmetric about the x axis and, for even n, about the origin: then it spans exactly
/// longAxis along x. For odd n it spans (1 + cos(π/n))/2 of longAxis.
std::vector<Vec2> ellipsePolygon(double longAxis, double aspectRatio, int vertexCount);

/// `count` equal discs with centres evenly along the x axis, spanning exactly `longAxis` (m)
/// with width longAxis / aspectRatio (the discs' diameter), centred on the origin (the
/// union's centroid, by symmetry). Neighbours overlap when aspectRatio < count.
std::vector<ClumpMember> lineClump(double longAxis, double aspectRatio, int count);

/// Area (m²) of a simple polygon given counter-clockwise.
double polygonArea(std::span<const Vec2> vertices);

/// Smallest width (m) of a convex polygon: the least distance between two parallel lines
/// that enclose it, which for a polygon is attained with one line along an edge.
double polygonMinWidth(std::span<const Vec2> vertices);

/// Largest distance (m) of a vertex from the origin.
double polygonReach(std::span<const Vec2> vertices);

}  // namespace grainlab::specimen
