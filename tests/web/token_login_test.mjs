// The dashboard on a server that asks for a token (docs/security.md), end to end in Chromium:
// without the token the page says how to log in and shows no runs; the login URL that
// `grainlab serve` prints logs in, trades its token for an HttpOnly, SameSite=Strict cookie
// and takes it out of the address bar; then the runs list, a new run and its live stream all
// work on the cookie alone. A page on another origin cannot use the cookie to start a run.
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { check, runBrowserTest, screenshot, waitUntil, watchConsole } from './harness.mjs';

const TOKEN = 'browser-test-token-0123456789abcdef';
const tokenFile = join(mkdtempSync(join(tmpdir(), 'grainlab-token-')), 'token');
writeFileSync(tokenFile, `${TOKEN}\n`, { mode: 0o600 });

await runBrowserTest(['--token-file', tokenFile], async ({ server, browser }) => {
  const { base } = server;
  const loginLine = server.log().split('\n').find((line) => line.includes('login URL'));
  check('the server prints its login URL on loopback with a token file',
    loginLine === `grainlab serve: login URL: ${base}/?token=${TOKEN}`, loginLine);

  // A first visit without the token: a login form, and the API refuses.
  // (Its 401s are the point here, so its console is not watched.)
  const context = await browser.newContext({ viewport: { width: 1200, height: 900 } });
  const anonymous = await context.newPage();
  anonymous.setDefaultTimeout(30000);
  await anonymous.goto(`${base}/#/runs`);
  await anonymous.locator('#login').waitFor({ state: 'visible' });
  check('without the token the dashboard shows the login form', true);
  await screenshot(anonymous, 'token-login-form');
  await anonymous.close();

  // The form, in a browser profile of its own: a wrong token is said so, the right one logs in.
  const pasting = await browser.newContext();
  const form = await pasting.newPage();
  form.setDefaultTimeout(30000);
  await form.goto(`${base}/#/runs`);
  await form.locator('#login input[name="token"]').fill('not-the-token-at-all-0000');
  await form.locator('#login button').click();
  await form.getByText('That token was not accepted.').waitFor({ state: 'visible' });
  check('the form says when a pasted token is wrong', true);
  await form.locator('#login input[name="token"]').fill(TOKEN);
  await Promise.all([form.waitForEvent('load'), form.locator('#login button').click()]);
  await form.locator('.server-state').waitFor({ state: 'visible' });
  const pasted = (await pasting.cookies(base)).find((c) => c.name.startsWith('grainlab_token_'));
  check('the right token pasted there logs in (cookie set, form gone after the reload)',
    pasted?.value === TOKEN && pasted?.httpOnly && !(await form.locator('#login').isVisible()));
  await pasting.close();

  // Through the login URL.
  const page = await context.newPage();
  page.setDefaultTimeout(30000);
  const consoleWatch = watchConsole(page);
  await page.goto(`${base}/?token=${TOKEN}#/runs`);
  await waitUntil(async () => !page.url().includes('token'), 10);
  check('the token is taken out of the address bar', !page.url().includes('token') && page.url().endsWith('#/runs'), page.url());
  // The address bar is cleaned before the trade is answered: wait for the answer's cookie.
  const cookie = await waitUntil(async () =>
    (await context.cookies(base)).find((c) => c.name.startsWith('grainlab_token_')), 10);
  check('it is kept in a cookie for this port', cookie?.name === `grainlab_token_${new URL(base).port}` && cookie?.value === TOKEN);
  check('...HttpOnly and SameSite=Strict', cookie?.httpOnly === true && cookie?.sameSite === 'Strict', JSON.stringify(cookie));
  check('...out of reach of the page\'s scripts', !(await page.evaluate(() => document.cookie)).includes(TOKEN));
  check('no login form once logged in', !(await page.locator('#login').isVisible()));

  // The whole dashboard on the cookie: start a run from the page, watch it live, see it listed.
  const created = await page.evaluate(async () => {
    const response = await fetch('/api/runs', { method: 'POST', headers: { 'content-type': 'application/json' },
      body: JSON.stringify({ preset: 'circular-quick' }) });
    return { status: response.status, body: await response.json() };
  });
  check('the page starts a run with the cookie alone', created.status === 201, JSON.stringify(created));
  await page.goto(`${base}/#/run/${created.body.id}`);
  const streamed = await waitUntil(() => page.$eval('canvas.particle-canvas', (c) => c.dataset.step !== undefined), 60);
  check('the run view draws frames from the live stream (the WebSocket is let in)', Boolean(streamed));
  const completed = await waitUntil(async () =>
    (await page.locator('.run-header .status').getAttribute('data-status')) === 'completed', 180);
  check('the run completes in the run view', Boolean(completed));
  await page.goto(`${base}/#/runs`);
  await page.locator('table.runs').getByText('circular-quick').first().waitFor({ state: 'visible' });
  check('the runs list shows it', true);
  await screenshot(page, 'token-logged-in');

  // Another site's page in the same browser: the cookie is not sent, and the Origin is refused.
  const other = await context.newPage();
  await other.goto('about:blank');
  const crossSite = await other.evaluate(async (url) => {
    try {
      await fetch(`${url}/api/runs`, { method: 'POST', mode: 'no-cors', body: '{"preset":"circular-quick"}' });
    } catch { /* opaque either way */ }
    return true;
  }, base);
  const runs = await (await fetch(`${base}/api/runs`, { headers: { authorization: `Bearer ${TOKEN}` } })).json();
  check('a cross-site POST in the same browser starts nothing', crossSite && runs.runs.length === 1, `${runs.runs.length} runs`);
  check('no console errors, page exceptions or failed requests', consoleWatch.errors.length === 0, consoleWatch.errors.join('\n'));
  await context.close();
});
