// Logging in to a server that asks for a token (docs/security.md). The login URL that
// `grainlab serve` prints carries ?token=: it is traded once for the server's HttpOnly,
// SameSite=Strict cookie and taken out of the address bar (and so out of history and of
// what a screenshot shows). Without it, a 401 from the API shows a form to paste the token in.

async function trade(token) {
  const response = await fetch('/api/session', { method: 'POST', headers: { authorization: `Bearer ${token}` } });
  return response.ok;
}

/** Before the first API call: uses and removes ?token= from the address bar, if there. */
export async function loginFromAddressBar() {
  const params = new URLSearchParams(location.search);
  const token = params.get('token');
  if (token === null) return;
  params.delete('token');
  const rest = params.toString();
  history.replaceState(null, '', `${location.pathname}${rest ? `?${rest}` : ''}${location.hash}`);
  if (!(await trade(token))) showLoginForm('The token in that link was not accepted.');
}

/** Asks for the token; once it is accepted the page starts again with the cookie. */
export function showLoginForm(reason = 'This server asks for a token.') {
  if (document.getElementById('login')) return;
  const form = document.createElement('form');
  form.id = 'login';
  form.className = 'login';
  form.innerHTML = `<p></p>
    <p>Open the login URL that <code>grainlab serve</code> printed, or paste its token here.</p>
    <input type="password" name="token" autocomplete="current-password" aria-label="token" required>
    <button type="submit">Log in</button>`;
  form.querySelector('p').textContent = reason;
  form.addEventListener('submit', async (event) => {
    event.preventDefault();
    if (await trade(form.elements.token.value.trim())) location.reload();
    else form.querySelector('p').textContent = 'That token was not accepted.';
  });
  document.body.prepend(form);
}
