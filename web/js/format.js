// Number, time and unit formatting shared by the views.

/** A number with `digits` significant digits, or an en dash for a missing value. */
export function sig(value, digits = 3) {
  if (value === null || value === undefined || !Number.isFinite(value)) return '–';
  if (value === 0) return '0';
  const magnitude = Math.abs(value);
  if (magnitude >= 1e5 || magnitude < 1e-3) return value.toExponential(digits - 1);
  return Number(value.toPrecision(digits)).toString();
}

export function percent(fraction, digits = 0) {
  return `${(100 * (fraction ?? 0)).toFixed(digits)} %`;
}

/** ISO time → local "2025-01-31 12:00:03". */
export function localTime(iso) {
  if (!iso) return '–';
  const d = new Date(iso);
  const pad = (n) => String(n).padStart(2, '0');
  return `${d.getFullYear()}-${pad(d.getMonth() + 1)}-${pad(d.getDate())} ${pad(d.getHours())}:${pad(d.getMinutes())}:${pad(d.getSeconds())}`;
}

/** Seconds → "42 s", "3 min 05 s", "1 h 02 min". */
export function duration(seconds) {
  if (seconds === null || seconds === undefined || !Number.isFinite(seconds)) return '–';
  const s = Math.max(0, Math.round(seconds));
  if (s < 60) return `${s} s`;
  if (s < 3600) return `${Math.floor(s / 60)} min ${String(s % 60).padStart(2, '0')} s`;
  return `${Math.floor(s / 3600)} h ${String(Math.floor((s % 3600) / 60)).padStart(2, '0')} min`;
}

/** A force per metre (N/m) with a readable prefix. */
export function forcePerMetre(value) {
  if (!Number.isFinite(value)) return '–';
  const magnitude = Math.abs(value);
  if (magnitude >= 1e6) return `${sig(value / 1e6)} MN/m`;
  if (magnitude >= 1e3) return `${sig(value / 1e3)} kN/m`;
  return `${sig(value)} N/m`;
}

/** A length in metres shown in mm. */
export function millimetres(value) {
  return Number.isFinite(value) ? `${sig(value * 1e3)} mm` : '–';
}

export const TERMINAL_STATUSES = new Set(['completed', 'failed', 'cancelled', 'interrupted']);

/**
 * A study's time left as the server estimates it (seconds_left, seconds_left_basis): null
 * when nothing is left to run or it cannot be told; else {text, title}.
 */
export function timeLeft(study) {
  const seconds = study.seconds_left;
  const basis = study.seconds_left_basis;
  if (basis === 'done' || basis === undefined) return null;
  if (seconds === null || seconds === undefined) return { text: 'time left unknown', title: 'a run left has no estimated wall time' };
  if (basis === 'measured') {
    const runs = study.pace?.runs_measured;
    return { text: `about ${duration(seconds)} left`,
      title: `the runs' estimated seconds at the pace the ${runs} finished run${runs === 1 ? '' : 's'} kept (wall time ${sig(study.pace?.wall_over_estimate)} × estimate)` };
  }
  return { text: `at least ${duration(seconds)} left`, title: "the runs' estimated seconds (no run has finished yet to measure the pace by)" };
}
