// What the browser tests share: a real `aerobreak serve` on a free loopback port with a fresh store,
// Debian's Chromium driven by playwright-core (no browser download), a page that may talk to
// that server only (every other request is aborted and recorded), and a screenshot of the page
// when a test fails. Every wait is bounded; the server and the browser are stopped in after().
import { spawn } from 'node:child_process';
import { mkdtempSync, readFileSync, existsSync, mkdirSync, writeFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { setTimeout as sleep } from 'node:timers/promises';
import { after, before } from 'node:test';
import { chromium } from 'playwright-core';

export const binary = process.env.AEROBREAK_BINARY;
export const screenshotDirectory = process.env.AEROBREAK_SCREENSHOT_DIR || path.join(tmpdir(), 'aerobreak-screenshots');
const chromiumPath = process.env.AEROBREAK_CHROMIUM || '/usr/bin/chromium';

// Flags for a sandboxed machine without network: no first-run, no background or component
// traffic, no GPU (docs/WEB.md).
export const chromiumArguments = ['--headless=new', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync', '--disable-dev-shm-usage'];

export async function until(condition, { timeoutMs = 30000, intervalMs = 100, what = 'a condition' } = {}) {
  const deadline = Date.now() + timeoutMs;
  for (;;) {
    const value = await condition();
    if (value) return value;
    if (Date.now() > deadline) throw new Error(`timed out after ${timeoutMs} ms waiting for ${what}`);
    await sleep(intervalMs);
  }
}

export class Service {
  // `arguments_`: more options of `aerobreak serve` (e.g. --token-file); `store`: a store file to
  // serve instead of a fresh one; `ranks`: of each worker job; `environment`: more variables of the
  // service (and so of its workers).
  static async start(arguments_ = [], { store, ranks = 2, environment = {} } = {}) {
    if (!binary || !existsSync(binary)) throw new Error('AEROBREAK_BINARY must name the built aerobreak');
    const directory = mkdtempSync(path.join(tmpdir(), 'aerobreak-browser-'));
    const portFile = path.join(directory, 'port');
    const storeFile = store || path.join(directory, 'store.sqlite');
    const child = spawn(binary, ['serve', '--store', storeFile, '--port', '0', '--port-file', portFile,
      '--ranks', String(ranks), '--idle-shutdown', '1', ...arguments_],
    { stdio: ['ignore', 'ignore', 'pipe'], env: { ...process.env, ...environment } });
    let log = '';
    child.stderr.on('data', (chunk) => { log += chunk; });
    const service = new Service(child, directory, () => log);
    await until(() => existsSync(portFile) || child.exitCode !== null, { what: 'aerobreak serve to listen' });
    if (child.exitCode !== null) throw new Error(`aerobreak serve exited: ${log}`);
    service.port = Number(readFileSync(portFile, 'utf8'));
    service.origin = `http://127.0.0.1:${service.port}`;
    return service;
  }

  constructor(child, directory, log) {
    this.child = child;
    this.directory = directory;
    this.log = log;
  }

  async request(method, apiPath, body, headers = {}) {
    const response = await fetch(`${this.origin}${apiPath}`, {
      method, body: body === undefined ? undefined : JSON.stringify(body),
      headers: body === undefined ? headers : { 'Content-Type': 'application/json', ...headers },
    });
    const text = await response.text();
    return { status: response.status, body: text ? JSON.parse(text) : null };
  }

  async get(apiPath) {
    const { status, body } = await this.request('GET', apiPath);
    if (status !== 200) throw new Error(`GET ${apiPath}: ${status} ${JSON.stringify(body)}`);
    return body;
  }

  async submit(study, headers) {
    const { status, body } = await this.request('POST', '/api/studies', study, headers);
    if (status !== 201) throw new Error(`submit: ${status} ${JSON.stringify(body)}`);
    return body.id;
  }

  async waitComplete(studyId, timeoutMs = 120000) {
    await until(async () => (await this.get(`/api/studies/${studyId}/progress`)).complete,
      { timeoutMs, intervalMs: 250, what: `study ${studyId} to finish` });
  }

  // SIGTERM (the service stops its worker job and requeues), SIGKILL after 10 s.
  async stop() {
    if (this.child.exitCode === null && this.child.signalCode === null) {
      const ended = new Promise((resolve) => this.child.once('exit', resolve));
      this.child.kill('SIGTERM');
      const timer = setTimeout(() => this.child.kill('SIGKILL'), 10000);
      await ended;
      clearTimeout(timer);
    }
    rmSync(this.directory, { recursive: true, force: true });
  }
}

// A browser page that may reach `service` only. page.foreignRequests lists what was refused;
// page.problems collects page errors, console errors and Content-Security-Policy violations.
export async function openPage(browser, service) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 }, acceptDownloads: true });
  const page = await context.newPage();
  page.foreignRequests = [];
  page.problems = [];
  await context.route('**/*', (route) => {
    const url = new URL(route.request().url());
    if (url.origin === service.origin) return route.continue();
    page.foreignRequests.push(url.href);
    return route.abort('blockedbyclient');
  });
  await context.addInitScript(() => {
    document.addEventListener('securitypolicyviolation', (event) => {
      console.error(`CSP violation: ${event.violatedDirective} ${event.blockedURI}`);
    });
  });
  page.on('pageerror', (error) => page.problems.push(`page error: ${error.message}`));
  page.on('console', (message) => {
    if (message.type() === 'error' && !/status of 40[14]/.test(message.text()))
      page.problems.push(`console: ${message.text()}`);
  });
  return page;
}

export function launchBrowser() {
  return chromium.launch({ executablePath: chromiumPath, args: chromiumArguments });
}

// A service with a fresh store and a browser, started before a file's tests (handed to
// `started({ service, browser })`) and stopped after them.
export function serviceAndBrowser(started) {
  const shared = {};
  before(async () => {
    shared.service = await Service.start();
    shared.browser = await launchBrowser();
    started(shared);
  });
  after(async () => {
    await shared.browser?.close();
    await shared.service?.stop();
  });
}

// Runs `body`; on failure writes a full-page screenshot named after the test, then fails.
export async function withScreenshot(page, name, body) {
  try {
    await body();
  } catch (error) {
    mkdirSync(screenshotDirectory, { recursive: true });
    const file = path.join(screenshotDirectory, `${name.replace(/[^A-Za-z0-9_-]+/g, '_')}.png`);
    await page.screenshot({ path: file, fullPage: true }).catch(() => {});
    writeFileSync(`${file}.txt`, `${error.stack}\n`);
    error.message += `\n(screenshot: ${file})`;
    throw error;
  }
}

// A study of ballistic clusters small enough for tests: every combination of `speeds`,
// `primaries` and `gammas`, `replicates` each.
export function smallStudy(name,
  { speeds, primaries = [8, 16], gammas = [0.001, 0.01], replicates = 2, description = '' }) {
  return {
    name, description,
    base: {
      cluster: { generator: { method: 'ballistic' } },
      model: { damping: { law: 'viscoelastic', dissipative_time: 0.05 } },
      run: { time_limit: 20000 },
    },
    axes: { impact_speed: { values: speeds }, gamma_over_kn: { values: gammas }, primaries: { values: primaries } },
    replicates: { count: replicates, seed: 7 },
    execution: { max_attempts: 2, case_wall_time: 600 },
  };
}
