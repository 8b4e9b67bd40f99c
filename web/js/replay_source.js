// A finished run's stored replay data from REST: the frame index and the frames themselves
// (GET .../frames?index=k, cached), and every stored histogram message.
import { api } from './api.js';
import { decodeFrame } from './frame_codec.js';

const CACHE_FRAMES = 48;

export class ReplaySource {
  constructor(id) {
    this.id = id;
    this.frames = [];      // [{index, step, time, bytes}], ascending step
    this.histograms = [];  // [{seq, step, histograms, ...}], ascending seq
    this.cache = new Map();
    this.inflight = new Map();
  }

  async load() {
    const [index, histograms] = await Promise.all([api.frameIndex(this.id), api.histograms(this.id)]);
    this.frames = index.frames.slice().sort((a, b) => a.step - b.step);
    this.histograms = histograms.histograms.slice().sort((a, b) => a.seq - b.seq);
  }

  /**
   * The stored frame nearest to `step`, or null. Frames are stored every few samples plus the
   * final state, which a cancelled run reaches after its last sample: nearest, not "at or
   * before", shows that final state at the slider's end.
   */
  frameNearest(step) {
    const before = lastAtOrBefore(this.frames, step, (f) => f.step);
    const after = before ? this.frames[this.frames.indexOf(before) + 1] : this.frames[0];
    if (!before) return after ?? null;
    if (!after) return before;
    return step - before.step <= after.step - step ? before : after;
  }

  /** The stored histogram message at or before sample `seq`, or null. */
  histogramAt(seq) {
    return lastAtOrBefore(this.histograms, seq, (h) => h.seq) ?? null;
  }

  /** Resolves to the decoded frame; concurrent requests for one index share the fetch. */
  async frame(info) {
    if (this.cache.has(info.index)) {
      const frame = this.cache.get(info.index);
      this.cache.delete(info.index);  // re-insert: most recently used last
      this.cache.set(info.index, frame);
      return frame;
    }
    if (!this.inflight.has(info.index)) {
      const request = api.frame(this.id, info.index).then((buffer) => {
        const frame = decodeFrame(buffer);
        this.cache.set(info.index, frame);
        if (this.cache.size > CACHE_FRAMES) this.cache.delete(this.cache.keys().next().value);
        return frame;
      }).finally(() => this.inflight.delete(info.index));
      this.inflight.set(info.index, request);
    }
    return this.inflight.get(info.index);
  }
}

function lastAtOrBefore(sorted, key, keyOf) {
  let lo = 0, hi = sorted.length - 1, found = null;
  while (lo <= hi) {
    const mid = (lo + hi) >> 1;
    if (keyOf(sorted[mid]) <= key) {
      found = sorted[mid];
      lo = mid + 1;
    } else {
      hi = mid - 1;
    }
  }
  return found;
}
