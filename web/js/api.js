// The REST API (docs/http-api.md, contracts.md): one function per endpoint. Failures throw
// ApiError carrying the server's {"error", "field"} so forms can show them beside the field.
import { showLoginForm } from './login.js';

export class ApiError extends Error {
  constructor(status, message, field) {
    super(message);
    this.status = status;
    this.field = field ?? null;
  }
}

async function request(method, path, { body, expect = 'json' } = {}) {
  const init = { method, headers: {} };
  if (body !== undefined) {
    init.body = JSON.stringify(body);
    init.headers['content-type'] = 'application/json';
  }
  let response;
  try {
    response = await fetch(path, init);
  } catch (error) {
    throw new ApiError(0, `the server cannot be reached (${error.message})`);
  }
  if (response.status === 401) showLoginForm();
  if (!response.ok) {
    let message = `${response.status} ${response.statusText}`;
    let field = null;
    const text = await response.text();
    try {
      const parsed = JSON.parse(text);
      message = parsed.error ?? message;
      field = parsed.field ?? null;
    } catch {
      if (text.trim()) message = text.trim();
    }
    throw new ApiError(response.status, message, field);
  }
  if (response.status === 204) return null;
  if (expect === 'binary') return response.arrayBuffer();
  if (expect === 'text') return response.text();
  return response.json();
}

const runPath = (id) => `/api/runs/${encodeURIComponent(id)}`;

export const api = {
  health: () => request('GET', '/api/health'),
  presets: async () => (await request('GET', '/api/presets')).presets,
  preset: (name) => request('GET', `/api/presets/${encodeURIComponent(name)}`),
  /**
   * One page of the runs list, filtered and sorted on the server: `params` among limit,
   * offset, status, preset, study, q, sort, order (empty values are left out).
   * Resolves to {runs, total, offset, limit, next}.
   */
  runsPage: (params) => {
    const query = new URLSearchParams();
    for (const [key, value] of Object.entries(params)) {
      if (value !== undefined && value !== null && value !== '') query.set(key, String(value));
    }
    return request('GET', `/api/runs?${query}`);
  },
  /** [{name, runs, by_status, status, progress, runs_url, source}]: launched and imported studies. */
  studies: async () => (await request('GET', '/api/studies')).studies,
  /** One study; a launched one with its spec and run_parameters. */
  study: (name) => request('GET', `/api/studies/${encodeURIComponent(name)}`),
  /** A sweep spec ({name, base, vary, mode}); resolves to the new study. */
  launchStudy: (spec) => request('POST', '/api/studies', { body: spec }),
  cancelStudy: (name) => request('POST', `/api/studies/${encodeURIComponent(name)}/cancel`),
  /** Deletes the study with its runs and their files. */
  deleteStudy: (name) => request('DELETE', `/api/studies/${encodeURIComponent(name)}`, { expect: 'text' }),
  /** A paper study's findings ({findings: [{number, claim, verdict, checks: [...]}], csv}), once its runs have ended. */
  studyFindings: (name) => request('GET', `/api/studies/${encodeURIComponent(name)}/findings`),
  /** A trade-off study's table ({panels: [{title, noise_floor_deg, points: [...]}], csv, runs_csv}), once its runs have ended. */
  studyTradeoff: (name) => request('GET', `/api/studies/${encodeURIComponent(name)}/tradeoff`),
  /** A cancelled or interrupted study's runs queued again, from their checkpoints where they have one. */
  resumeStudy: (name) => request('POST', `/api/studies/${encodeURIComponent(name)}/resume`),
  /**
   * A study's ensemble bands, computed on the server from its completed runs' series:
   * {quantity, title, group_by, paths, runs, grid, groups: [{value, ids, mean, low, high, n}]}.
   * `group` '' puts every run in one group; undefined lets the server pick the first varied path.
   */
  studyBands: (name, quantity, group) => {
    const query = new URLSearchParams({ quantity });
    if (group !== undefined) query.set('group', group);
    return request('GET', `/api/studies/${encodeURIComponent(name)}/bands?${query}`);
  },
  run: (id) => request('GET', runPath(id)),
  /** A scene object or {preset: NAME}; resolves to the new run's id. */
  createRun: async (body) => (await request('POST', '/api/runs', { body })).id,
  cancel: (id) => request('POST', `${runPath(id)}/cancel`),
  /** An interrupted run (or one stopped at the wall-time limit) continues from its checkpoint. */
  resume: (id) => request('POST', `${runPath(id)}/resume`),
  remove: (id) => request('DELETE', runPath(id)),
  /** {id, columns, rows: [[...]]} */
  series: (id) => request('GET', `${runPath(id)}/series`),
  /** {id, histograms: [{type, seq, step, time, stage, histograms}]} */
  histograms: (id) => request('GET', `${runPath(id)}/histograms`),
  /** {id, frames: [{index, step, time, bytes}]} */
  frameIndex: (id) => request('GET', `${runPath(id)}/frames`),
  frame: (id, index) => request('GET', `${runPath(id)}/frames?index=${index}`, { expect: 'binary' }),
  shapes: (id) => request('GET', `${runPath(id)}/shapes`),
  csvUrl: (id) => `${runPath(id)}/series?format=csv`,
  streamUrl: (id) => {
    const scheme = location.protocol === 'https:' ? 'wss' : 'ws';
    return `${scheme}://${location.host}${runPath(id)}/stream`;
  },
};
