// Where a periodic cell's particles are drawn: each particle wrapped into the cell, and for a
// particle whose bounding circle crosses an edge, its images on the other side(s), so the
// packing looks continuous inside the cell's outline. A force chain across an edge is drawn to
// the nearest image of its other particle. The cell is the frame's edges h1, h2 (m), one
// corner at the origin, as the engine's PeriodicCell (docs/periodic-cell.md).

/** The cell's corners [x0, y0, x1, y1, x2, y2, x3, y3]: 0, h1, h1 + h2, h2 (counter-clockwise). */
export function cellCorners([h1x, h1y, h2x, h2y]) {
  return [0, 0, h1x, h1y, h1x + h2x, h1y + h2y, h2x, h2y];
}

/**
 * The particles' drawn places in the cell `cell` = [h1x, h1y, h2x, h2y]:
 * {x, y} (Float64Array, each particle wrapped into the cell) and images, a flat
 * [i, x, y, i, x, y, ...] of the extra copies of particles whose bounding circle (radius[i])
 * reaches across an edge (the copy's centre is x + h n, n ∈ {-1, 0, 1}², n ≠ 0, and its circle
 * overlaps the cell).
 */
export function placeInCell(cell, particles, count, radius) {
  const [ax, ay, bx, by] = cell;
  const area = ax * by - ay * bx;
  // Fractional coordinates s = h⁻¹ x; a circle of radius r reaches r·|h2|/A across s1 and
  // r·|h1|/A across s2 (the cell's widths are A/|h2| and A/|h1|).
  const len1 = Math.hypot(ax, ay), len2 = Math.hypot(bx, by);
  const x = new Float64Array(count), y = new Float64Array(count);
  const images = [];
  for (let i = 0; i < count; i++) {
    const px = particles[4 * i], py = particles[4 * i + 1];
    let s1 = (by * px - bx * py) / area, s2 = (-ay * px + ax * py) / area;
    s1 -= Math.floor(s1);
    s2 -= Math.floor(s2);
    x[i] = ax * s1 + bx * s2;
    y[i] = ay * s1 + by * s2;
    const m1 = (radius[i] * len2) / area, m2 = (radius[i] * len1) / area;
    for (let n1 = -1; n1 <= 1; n1++) {
      const t1 = s1 + n1;
      if (t1 + m1 <= 0 || t1 - m1 >= 1) continue;
      for (let n2 = -1; n2 <= 1; n2++) {
        if (n1 === 0 && n2 === 0) continue;
        const t2 = s2 + n2;
        if (t2 + m2 <= 0 || t2 - m2 >= 1) continue;
        images.push(i, x[i] + ax * n1 + bx * n2, y[i] + ay * n1 + by * n2);
      }
    }
  }
  return { x, y, images };
}

/**
 * The shortest of d + h n over the integers n: [dx, dy]. The engine keeps its cell reduced
 * (each edge's projection on the other at most about half of it), where the nearest image is
 * within one step of the rounded fractional coordinates; those nine are searched.
 */
export function nearestImage(cell, dx, dy) {
  const [ax, ay, bx, by] = cell;
  const area = ax * by - ay * bx;
  const r1 = Math.round((by * dx - bx * dy) / area), r2 = Math.round((-ay * dx + ax * dy) / area);
  let best = [dx, dy], bestLength = Infinity;
  for (let n1 = -r1 - 1; n1 <= -r1 + 1; n1++) {
    for (let n2 = -r2 - 1; n2 <= -r2 + 1; n2++) {
      const ex = dx + ax * n1 + bx * n2, ey = dy + ay * n1 + by * n2;
      const length = ex * ex + ey * ey;
      if (length < bestLength) {
        bestLength = length;
        best = [ex, ey];
      }
    }
  }
  return best;
}
