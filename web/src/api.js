// The REST API (schemas/openapi.json), same origin only. POSTs send JSON with its content type and,
// once the service has asked for it (401), the bearer token the user gave.
import { askForToken, forgetToken, storedToken } from './views/token.js';

export class ApiError extends Error {
  constructor(status, body) {
    super((body && body.error) || `HTTP ${status}`);
    this.status = status;
    this.body = body;
  }
}

async function parse(response) {
  const type = response.headers.get('Content-Type') || '';
  const body = type.includes('application/json') ? await response.json() : null;
  if (!response.ok) throw new ApiError(response.status, body);
  return body;
}

export async function getJson(path, { signal } = {}) {
  return parse(await fetch(path, { signal, headers: { Accept: 'application/json' } }));
}

// The JSON at `path`, or null where the service answers 404 (e.g. a study without results or
// without a search).
export async function getJsonOrNull(path) {
  try {
    return await getJson(path);
  } catch (error) {
    if (error instanceof ApiError && error.status === 404) return null;
    throw error;
  }
}

function post(path, body, token) {
  const headers = { 'Content-Type': 'application/json', Accept: 'application/json' };
  if (token) headers.Authorization = `Bearer ${token}`;
  return fetch(path, { method: 'POST', headers, body });
}

// POSTs `bodyText`; on 401 asks the user for the token and tries again with it.
export async function postJson(path, bodyText = '{}') {
  let response = await post(path, bodyText, storedToken());
  while (response.status === 401) {
    forgetToken();
    const token = await askForToken();
    if (!token) throw new ApiError(401, { error: 'a bearer token is needed and none was given' });
    response = await post(path, bodyText, token);
  }
  return { status: response.status, body: await parse(response) };
}

// URL query from an object, leaving out empty values.
export function query(parameters) {
  const search = new URLSearchParams();
  for (const [name, value] of Object.entries(parameters)) {
    if (value === undefined || value === null || value === '') continue;
    search.append(name, String(value));
  }
  const text = search.toString();
  return text ? `?${text}` : '';
}
