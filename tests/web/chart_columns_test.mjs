// The dashboard's chart catalogue (web/js/chart_specs.js) reads only columns that series.csv
// has: every quantity of every run chart, compare chart and x axis is evaluated on a table that
// records the names asked for, and each name must be in `grainlab columns --json` (the one
// table of the columns). A renamed column then fails here, not as an empty chart.
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const cli = process.env.GRAINLAB_CLI;
const web = process.env.GRAINLAB_WEB;
const known = new Set(JSON.parse(execFileSync(cli, ['columns', '--json']).toString()).columns.map((c) => c.name));
const specs = await import(pathToFileURL(join(web, 'js', 'chart_specs.js')).href);

const asked = new Set();
const table = {
  length: 3,
  column(name) {
    asked.add(name);
    return name === 'stage' ? ['shearing', 'shearing', 'shearing'] : [0.1, 0.2, 0.3];
  },
};
const rows = [0, 1, 2];
const quantities = [
  ...Object.values(specs.X_AXES).map((x) => x.values),
  ...specs.RUN_CHARTS.flatMap((chart) => chart.series.map((s) => s.values)),
  ...specs.COMPARE_CHARTS.map((chart) => chart.values),
];
for (const values of quantities) values(table, rows);
specs.chartDomain(table, specs.X_AXES.strain, new Set(['shearing']));

const unknown = [...asked].filter((name) => !known.has(name));
console.log(`${quantities.length} quantities read ${asked.size} columns; ${known.size} columns in the table`);
if (asked.size < 20 || unknown.length > 0) {
  console.log(`FAIL - columns the charts read that series.csv does not have: ${unknown.join(', ') || '(none)'}`);
  process.exit(1);
}
console.log('ok   - every column the charts read is in the table');
