// The run's WebSocket (/api/runs/{id}/stream): JSON text messages by "type" (shapes, status,
// sample, histogram) and binary particle frames. A late joiner first receives the run's state
// so far (shapes, status, the samples, the latest histogram and frame), then live messages;
// the server closes the socket after the final status.
import { api } from './api.js';
import { decodeFrame } from './frame_codec.js';

export class RunStream {
  /**
   * @param {number} id
   * @param {{onShapes, onStatus, onSample, onHistogram, onFrame, onClose}} handlers
   *   onClose(cleanly) — cleanly is false when the connection broke.
   */
  constructor(id, handlers) {
    this.id = id;
    this.handlers = handlers;
    this.socket = null;
    this.closedByUs = false;
  }

  open() {
    const socket = new WebSocket(api.streamUrl(this.id));
    socket.binaryType = 'arraybuffer';
    socket.onmessage = (event) => this.dispatch(event.data);
    socket.onclose = (event) => {
      if (this.socket !== socket) return;
      this.socket = null;
      if (!this.closedByUs) this.handlers.onClose?.(event.wasClean);
    };
    this.socket = socket;
  }

  close() {
    this.closedByUs = true;
    if (this.socket) {
      const socket = this.socket;
      this.socket = null;
      // Closing while still connecting makes Chromium log an error: wait for the handshake.
      if (socket.readyState === WebSocket.CONNECTING) socket.onopen = () => socket.close();
      else socket.close();
    }
  }

  dispatch(data) {
    if (data instanceof ArrayBuffer) {
      this.handlers.onFrame?.(decodeFrame(data));
      return;
    }
    const message = JSON.parse(data);
    switch (message.type) {
      case 'shapes': this.handlers.onShapes?.(message); break;
      case 'status': this.handlers.onStatus?.(message); break;
      case 'sample': this.handlers.onSample?.(message); break;
      case 'histogram': this.handlers.onHistogram?.(message); break;
      default: break;  // newer message types: ignored by this dashboard
    }
  }
}
