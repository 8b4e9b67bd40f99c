// The dashboard's entry: a hash router over the views (#/runs, #/new, #/run/ID, #/compare,
// #/studies, #/studies/NAME)
// and the server's health in the top bar.
import { api } from './api.js';
import { runsView } from './views/runs_view.js';
import { newRunView } from './views/new_run_view.js';
import { runView } from './views/run_view.js';
import { compareView } from './views/compare_view.js';
import { studiesView } from './views/studies_view.js';
import { studyView } from './views/study_view.js';
import { loginFromAddressBar } from './login.js';

const HEALTH_MS = 10000;
const viewRoot = document.getElementById('view');
let current = null;

function route() {
  const hash = location.hash.replace(/^#/, '') || '/runs';
  const [path, query = ''] = hash.split('?');
  const params = new URLSearchParams(query);
  current?.destroy();
  current = null;
  viewRoot.replaceChildren();
  let nav = 'runs';
  const runMatch = /^\/run\/(\d+)$/.exec(path);
  const studyMatch = /^\/studies\/([^/]+)$/.exec(path);
  if (runMatch) {
    current = runView(viewRoot, Number(runMatch[1]));
  } else if (studyMatch) {
    nav = 'studies';
    current = studyView(viewRoot, decodeURIComponent(studyMatch[1]));
  } else if (path === '/studies') {
    nav = 'studies';
    current = studiesView(viewRoot);
  } else if (path === '/new') {
    nav = 'new';
    current = newRunView(viewRoot, params);
  } else if (path === '/compare') {
    nav = 'compare';
    current = compareView(viewRoot, params);
  } else {
    current = runsView(viewRoot, params);
  }
  for (const link of document.querySelectorAll('[data-nav]')) link.classList.toggle('active', link.dataset.nav === nav);
}

async function showHealth() {
  const badge = document.getElementById('server-state');
  try {
    const health = await api.health();
    badge.textContent = `server ${health.version} · ${health.runs.running} running · ${health.runs.queued} queued`;
    badge.classList.remove('down');
  } catch (error) {
    badge.textContent = `server unreachable (${error.message})`;
    badge.classList.add('down');
  }
  setTimeout(showHealth, HEALTH_MS);
}

await loginFromAddressBar();
window.addEventListener('hashchange', route);
route();
showHealth();
