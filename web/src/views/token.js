// The bearer token: asked for in a dialog when the service answers 401, kept for this tab only.
const kKey = 'aerobreak.token';

export function storedToken() {
  return sessionStorage.getItem(kKey);
}

export function forgetToken() {
  sessionStorage.removeItem(kKey);
}

export function askForToken() {
  const dialog = document.getElementById('token-dialog');
  const input = document.getElementById('token-input');
  input.value = '';
  return new Promise((resolve) => {
    dialog.addEventListener('close', () => {
      const token = dialog.returnValue === 'ok' ? input.value.trim() : '';
      if (token) sessionStorage.setItem(kKey, token);
      resolve(token || null);
    }, { once: true });
    dialog.showModal();
  });
}
