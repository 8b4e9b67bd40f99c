// The run's particle shapes (the stream's "shapes" message or GET /api/runs/{id}/shapes),
// flattened into typed arrays once so drawing a frame allocates nothing per particle.

export const DISC = 0;
export const POLYGON = 1;
export const CLUMP = 2;

/**
 * {count, shapes: [{disc: r} | {polygon: [x0, y0, ...]} | {clump: [x0, y0, r0, ...]}], boundary: [i...], walls: [...]}
 * → {count, kind, radius, vertexStart, vertices, memberStart, members, axisAngle, boundary, walls}.
 * Vertices and clump members (x, y, r) are in the body frame (centroid at the origin, angle 0).
 */
export function prepareShapes(message) {
  const count = message.count ?? message.shapes.length;
  const kind = new Uint8Array(count);
  const radius = new Float32Array(count);
  const axisAngle = new Float32Array(count);
  const vertexStart = new Uint32Array(count + 1);
  const memberStart = new Uint32Array(count + 1);
  let totalVertices = 0, totalMembers = 0;
  for (let i = 0; i < count; i++) {
    const shape = message.shapes[i];
    if (shape.polygon) totalVertices += shape.polygon.length / 2;
    if (shape.clump) totalMembers += shape.clump.length / 3;
  }
  const members = new Float32Array(totalMembers * 3);
  let memberAt = 0;
  const vertices = new Float32Array(totalVertices * 2);
  let at = 0;
  for (let i = 0; i < count; i++) {
    const shape = message.shapes[i];
    vertexStart[i] = at / 2;
    memberStart[i] = memberAt / 3;
    if (shape.clump) {
      // Drawn as its discs; its reach and long axis are its members'.
      kind[i] = CLUMP;
      const m = shape.clump;
      const centres = [];
      let farthest = 0;
      for (let k = 0; k < m.length; k += 3) {
        members[memberAt++] = m[k];
        members[memberAt++] = m[k + 1];
        members[memberAt++] = m[k + 2];
        centres.push(m[k], m[k + 1]);
        farthest = Math.max(farthest, Math.hypot(m[k], m[k + 1]) + m[k + 2]);
      }
      radius[i] = farthest;
      axisAngle[i] = longAxisAngle(centres);
    } else if (shape.polygon) {
      kind[i] = POLYGON;
      const v = shape.polygon;
      let farthest = 0;
      for (let k = 0; k < v.length; k += 2) {
        vertices[at++] = v[k];
        vertices[at++] = v[k + 1];
        farthest = Math.max(farthest, Math.hypot(v[k], v[k + 1]));
      }
      radius[i] = farthest;
      axisAngle[i] = longAxisAngle(v);
    } else {
      kind[i] = DISC;
      radius[i] = shape.disc;
    }
  }
  vertexStart[count] = at / 2;
  memberStart[count] = memberAt / 3;
  const boundary = new Uint8Array(count);
  for (const i of message.boundary ?? []) if (i >= 0 && i < count) boundary[i] = 1;
  return { count, kind, radius, vertexStart, vertices, memberStart, members, axisAngle, boundary, walls: message.walls ?? [] };
}

/** Direction (radians) of the polygon's long axis: the major principal axis of its vertices. */
function longAxisAngle(v) {
  let xx = 0, yy = 0, xy = 0;
  for (let k = 0; k < v.length; k += 2) {
    xx += v[k] * v[k];
    yy += v[k + 1] * v[k + 1];
    xy += v[k] * v[k + 1];
  }
  return 0.5 * Math.atan2(2 * xy, xx - yy);
}
