// Where the particle view draws a periodic cell's particles (web/js/cell_images.js): wrapped
// into the cell, an image for each edge a particle's circle crosses (two edges at a corner
// give three images), none for a particle inside, and chains to the true nearest image, checked
// against a brute-force search in a tilted cell. Node only.
import assert from 'node:assert/strict';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const { cellCorners, nearestImage, placeInCell } =
  await import(pathToFileURL(join(process.env.GRAINLAB_WEB, 'js', 'cell_images.js')).href);

// Frames carry positions as float32: a few ulps at 0.1 m (7e-9 m each) is the most placement
// can keep; the nearest image is computed in doubles.
const close = (a, b, what, tol = 3e-8) => assert.ok(Math.abs(a - b) < tol, `${what}: ${a} vs ${b}`);

// A cell with edges h1 = (0.04, 0.002), h2 = (0.015, 0.03): tilted and not square.
const cell = [0.04, 0.002, 0.015, 0.03];
assert.deepEqual(cellCorners(cell), [0, 0, 0.04, 0.002, 0.055, 0.032, 0.015, 0.03]);
const at = (s1, s2) => [cell[0] * s1 + cell[2] * s2, cell[1] * s1 + cell[3] * s2];
const r = 0.001;
const particles = [];
const put = ([x, y]) => particles.push(x, y, 0, 0);
put(at(0.5, 0.5));          // 0: well inside
put(at(0.01, 0.5));         // 1: just inside the edge along h2: one image at +h1
put(at(0.5, 1.01));         // 2: just outside the edge along h1 (written past it): wrapped to s2 = 0.01, one image at +h2
put(at(0.99, 0.995));       // 3: near the far corner: images at −h1, −h2 and −h1 − h2
put(at(-1.5, 2.5));         // 4: far outside, inside once wrapped
const radius = new Float32Array([r, r, r, r, r]);
const placed = placeInCell(cell, new Float32Array(particles), 5, radius);

const [x4, y4] = at(0.5, 0.5);
close(placed.x[4], x4, 'wrapped x');
close(placed.y[4], y4, 'wrapped y');
const [x2, y2] = at(0.5, 0.01);
close(placed.x[2], x2, 'a particle past an edge comes back in, x');
close(placed.y[2], y2, 'a particle past an edge comes back in, y');

const imagesOf = (i) => {
  const out = [];
  for (let a = 0; a < placed.images.length; a += 3) if (placed.images[a] === i) out.push([placed.images[a + 1], placed.images[a + 2]]);
  return out;
};
assert.equal(imagesOf(0).length, 0, 'a particle inside has no image');
assert.equal(imagesOf(4).length, 0, 'nor once wrapped');
const one = imagesOf(1);
assert.equal(one.length, 1, 'one edge crossed, one image');
close(one[0][0], placed.x[1] + cell[0], 'image across the edge at +h1, x');
close(one[0][1], placed.y[1] + cell[1], 'image across the edge at +h1, y');
assert.equal(imagesOf(2).length, 1);
close(imagesOf(2)[0][0], placed.x[2] + cell[2], 'image at +h2');
const corner = imagesOf(3).map(([x, y]) => [x - placed.x[3], y - placed.y[3]]);
assert.equal(corner.length, 3, 'a corner crossed: three images');
for (const [ex, ey] of [[-cell[0], -cell[1]], [-cell[2], -cell[3]], [-cell[0] - cell[2], -cell[1] - cell[3]]])
  assert.ok(corner.some(([dx, dy]) => Math.abs(dx - ex) < 3e-8 && Math.abs(dy - ey) < 3e-8), `image at ${ex}, ${ey}`);

// The view's minimum image against a brute-force search, in a cell tilted by just under half
// an edge (as the engine's reduced cells are) and in a square one.
for (const h of [cell, [0.03, 0, 0.0149, 0.02], [0.02, 0, 0, 0.02]]) {
  let seed = 7;
  const random = () => ((seed = (seed * 16807) % 2147483647) / 2147483647) * 0.2 - 0.1;
  for (let t = 0; t < 2000; t++) {
    const dx = random(), dy = random();
    let best = Infinity;
    for (let n1 = -20; n1 <= 20; n1++)
      for (let n2 = -20; n2 <= 20; n2++) best = Math.min(best, Math.hypot(dx + h[0] * n1 + h[2] * n2, dy + h[1] * n1 + h[3] * n2));
    const [ex, ey] = nearestImage(h, dx, dy);
    close(Math.hypot(ex, ey), best, `nearest image of ${dx}, ${dy}`, 1e-15);
  }
}
console.log('cell images: all checks passed');
