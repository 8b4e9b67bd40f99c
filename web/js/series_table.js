// A run's series as columns (contracts.md's names), filled from GET .../series or appended
// to from the stream's "sample" messages. Missing values are null.

export class SeriesTable {
  constructor(columns = []) {
    this.columns = [];
    this.index = new Map();
    this.data = [];
    this.seqs = [];
    for (const name of columns) this.addColumn(name);
  }

  /** From {columns, rows: [[...]]}: row k is sample seq k. */
  static fromRest(series) {
    const table = new SeriesTable(series.columns);
    series.rows.forEach((row, seq) => {
      table.seqs.push(seq);
      for (let c = 0; c < row.length; c++) table.data[c].push(row[c]);
    });
    return table;
  }

  addColumn(name) {
    this.index.set(name, this.columns.length);
    this.columns.push(name);
    this.data.push(new Array(this.seqs.length).fill(null));
  }

  get length() {
    return this.seqs.length;
  }

  get lastSeq() {
    return this.seqs.length ? this.seqs[this.seqs.length - 1] : -1;
  }

  /** A stream sample {seq, row: {column: value}}; repeats (a reconnect) are skipped. */
  appendSample(seq, row) {
    if (seq <= this.lastSeq) return false;
    for (const name of Object.keys(row)) if (!this.index.has(name)) this.addColumn(name);
    this.seqs.push(seq);
    for (let c = 0; c < this.columns.length; c++) this.data[c].push(row[this.columns[c]] ?? null);
    return true;
  }

  column(name) {
    const c = this.index.get(name);
    return c === undefined ? null : this.data[c];
  }

  /** Row i as {column: value}. */
  row(i) {
    if (i < 0 || i >= this.length) return null;
    const out = {};
    for (let c = 0; c < this.columns.length; c++) out[this.columns[c]] = this.data[c][i];
    return out;
  }

  /** The row of sample `seq`, or -1. */
  rowOfSeq(seq) {
    let lo = 0, hi = this.seqs.length - 1;
    while (lo <= hi) {
      const mid = (lo + hi) >> 1;
      if (this.seqs[mid] === seq) return mid;
      if (this.seqs[mid] < seq) lo = mid + 1;
      else hi = mid - 1;
    }
    return -1;
  }
}

/**
 * The names of a scene's shearing stages (biaxial, as the paper, or a loading path): the rows
 * plotted against axial strain or rotation angle.
 */
// lammps_deformation: an imported LAMMPS run's strain-controlled cell deformation.
const SHEARING = ['biaxial', 'rotation', 'cyclic', 'simple_shear', 'lammps_deformation'];
export function shearingStages(scene) {
  const names = new Set();
  for (const stage of scene?.stages ?? []) if (SHEARING.includes(stage.type)) names.add(stage.name ?? stage.type);
  return names;
}

/**
 * The x axis a scene's shearing reads best against: the rotation angle for a rotation, time
 * for simple shear (its axial strain stays near zero), axial strain otherwise.
 */
export function shearingAxis(scene) {
  const types = (scene?.stages ?? []).map((stage) => stage.type);
  if (types.includes('rotation')) return 'rotation';
  if (types.includes('simple_shear')) return 'time';
  return 'strain';
}
