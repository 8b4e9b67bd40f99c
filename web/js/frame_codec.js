// The stream's binary particle frame, version 1 (server/src/frame_codec.hpp):
//   0 "GLF1" | 4 u16 version | 6 u16 header bytes | 8 i64 step | 16 f64 time
//   24 u32 particles N | 28 u32 contacts M | 32 f32 max mean force | 36 f32 max contact f_n
//   [header ≥ 56: 40 f32 h1x, h1y, h2x, h2y, the periodic cell's edges, m]
//   then N × (f32 x, y, angle, mean |f|) and M × (u32 i, u32 j, f32 f_n), little-endian.
// Every offset is a multiple of 4, so typed arrays are laid over the buffer without copying.

const PARTICLE_WORDS = 4;
const CONTACT_WORDS = 3;
const HEADER_BYTES = 40;
const CELL_HEADER_BYTES = 56;

export function decodeFrame(buffer) {
  if (buffer.byteLength < 40) throw new Error('frame too short');
  const view = new DataView(buffer);
  const magic = String.fromCharCode(view.getUint8(0), view.getUint8(1), view.getUint8(2), view.getUint8(3));
  if (magic !== 'GLF1') throw new Error('not a grainlab frame');
  const version = view.getUint16(4, true);
  if (version !== 1) throw new Error(`unknown frame version ${version}`);
  const headerBytes = view.getUint16(6, true);
  if (headerBytes < HEADER_BYTES || headerBytes > buffer.byteLength) throw new Error('frame header size out of range');
  const count = view.getUint32(24, true);
  const contactCount = view.getUint32(28, true);
  const contactOffset = headerBytes + count * PARTICLE_WORDS * 4;
  if (buffer.byteLength !== contactOffset + contactCount * CONTACT_WORDS * 4) {
    throw new Error('frame size does not match its counts');
  }
  return {
    step: Number(view.getBigInt64(8, true)),
    time: view.getFloat64(16, true),
    count,
    contactCount,
    maxMeanForce: view.getFloat32(32, true),
    maxContactForce: view.getFloat32(36, true),
    /** The periodic cell's edge vectors [h1x, h1y, h2x, h2y] (m), or null for a run without one. */
    cell: headerBytes >= CELL_HEADER_BYTES
      ? [0, 1, 2, 3].map((k) => view.getFloat32(HEADER_BYTES + 4 * k, true))
      : null,
    /** x, y, angle, mean force per particle */
    particles: new Float32Array(buffer, headerBytes, count * PARTICLE_WORDS),
    /** i, j as integers (words 0 and 1 of each contact) */
    contactIndices: new Uint32Array(buffer, contactOffset, contactCount * CONTACT_WORDS),
    /** f_n as a float (word 2 of each contact) */
    contactForces: new Float32Array(buffer, contactOffset, contactCount * CONTACT_WORDS),
  };
}
