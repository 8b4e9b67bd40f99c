// scripts/reliability's table: the `figure {json}` lines of a run's log, grouped by section,
// as text on stdout and, with --markdown FILE, as markdown tables (for docs/reliability.md).
// Usage: node report.mjs LOG... [--markdown FILE] [--title TEXT] (several logs: one table)
import { readFileSync, writeFileSync } from 'node:fs';

const args = process.argv.slice(2);
const firstOption = args.findIndex((a) => a.startsWith('--'));
const logs = firstOption < 0 ? args : args.slice(0, firstOption);
const rest = firstOption < 0 ? [] : args.slice(firstOption);
const option = (name) => { const k = rest.indexOf(name); return k >= 0 ? rest[k + 1] : undefined; };
const lines = logs.flatMap((log) => readFileSync(log, 'utf8').split('\n'));
const figures = lines.filter((l) => l.startsWith('figure ')).map((l) => JSON.parse(l.slice(7)));
const failedChecks = lines.filter((l) => l.startsWith('FAIL - '));

const sections = new Map();
for (const f of figures) {
  if (!sections.has(f.section)) sections.set(f.section, []);
  sections.get(f.section).push(f);
}
const shown = (f) => `${f.value}${f.unit ? ` ${f.unit}` : ''}`;
const verdict = (f) => (f.ok === true ? 'met' : f.ok === false ? 'NOT MET' : '');

let text = '';
for (const [section, rows] of sections) {
  text += `\n${section}\n`;
  const width = Math.min(70, Math.max(...rows.map((r) => r.name.length)));
  for (const r of rows) {
    const target = r.target ? `  (target ${r.target}: ${verdict(r)})` : '';
    text += `  ${r.name.padEnd(width)}  ${shown(r)}${target}\n`;
  }
}
text += `\n${failedChecks.length} failed checks${failedChecks.length ? ':\n' + failedChecks.join('\n') : ''}\n`;
process.stdout.write(text);

const file = option('--markdown');
if (file) {
  const cell = (s) => String(s).replaceAll('|', '\\|');
  let md = option('--title') ? `${option('--title')}\n` : '';
  for (const [section, rows] of sections) {
    md += `\n**${section}**\n\n| figure | value | target | |\n| --- | --- | --- | --- |\n`;
    for (const r of rows) md += `| ${cell(r.name)} | ${cell(shown(r))} | ${cell(r.target)} | ${verdict(r)} |\n`;
  }
  if (failedChecks.length) md += `\nFailed checks:\n\n${failedChecks.map((c) => `- ${cell(c.slice(7))}`).join('\n')}\n`;
  writeFileSync(file, md);
}
process.exitCode = failedChecks.length || figures.some((f) => f.ok === false) ? 1 : 0;
