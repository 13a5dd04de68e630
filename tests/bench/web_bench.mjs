// A benchmark, not a test (docs/PERFORMANCE.md, "Dashboard"): times the study page of a store with
// 100,000 results in headless Chromium. Usage, from the repository root after scripts/setup.sh:
//   build/tests/dashboard_store_fill /tmp/big.sqlite   (a new file; once)
//   node tests/bench/web_bench.mjs /tmp/big.sqlite [RUNS]
// Prints, per run: the time from navigation to every plot and the case table drawn, the longest
// main-thread task while loading (Long Tasks API), the time to redraw the plots for another
// outcome, to filter the case table and to turn its page, and the requests of the load that took
// longest (Resource Timing: from the request's start to its last byte). The first run after the
// service starts is the cold one: the service then computes the grid statistics it keeps until the
// study changes. The correlations are fitted (and stored) once before the runs, since the page asks
// for them after it is drawn and a first fit of 100,000 results would weigh on the runs after it.
import { spawn } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { createRequire } from 'node:module';

const require = createRequire(new URL('../browser/package.json', import.meta.url));
const { chromium } = require('playwright-core');
const { chromiumArguments, until } = await import('../browser/support.mjs');

const [store, runsText = '5'] = process.argv.slice(2);
if (!store || !existsSync(store)) throw new Error('usage: node tests/bench/web_bench.mjs STORE.sqlite [RUNS]');
const binary = process.env.AEROBREAK_BINARY || path.resolve('build/aerobreak');
const scratch = mkdtempSync(path.join(tmpdir(), 'aerobreak-web-bench-'));
const portFile = path.join(scratch, 'port');
const server = spawn(binary, ['serve', '--store', store, '--data', scratch, '--port', '0', '--port-file', portFile, '--ranks', '1'],
  { stdio: 'ignore' });

function drawn() {
  const charts = ['plot-probability', 'plot-critical', 'plot-retained', 'plot-damage', 'plot-restitution', 'plot-fragments'];
  return charts.every((id) => document.getElementById(id)?.dataset.series !== undefined) &&
    document.querySelector('#case-table table') !== null;
}

async function oneRun(browser, origin) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 900 } });
  await page.addInitScript(() => {
    window.longTasks = [];
    new PerformanceObserver((list) => window.longTasks.push(...list.getEntries().map((e) => e.duration)))
      .observe({ type: 'longtask', buffered: true });
  });
  await page.goto(`${origin}/?study=1`);
  await page.waitForFunction(drawn, null, { timeout: 60000, polling: 10 });
  const load = await page.evaluate(() => performance.now());
  const longest = await page.evaluate(() => Math.max(0, ...window.longTasks));
  const requests = await page.evaluate(() => performance.getEntriesByType('resource')
    .filter((entry) => entry.name.includes('/api/')).sort((a, b) => b.duration - a.duration).slice(0, 3)
    .map((entry) => `${new URL(entry.name).pathname} ${entry.duration.toFixed(0)} ms`).join(', '));
  const redraw = await page.evaluate(() => {
    const start = performance.now();
    const choice = document.getElementById('choose-outcome');
    choice.value = 'stick';
    choice.dispatchEvent(new Event('change'));
    return performance.now() - start;
  });
  const timeTable = async (action) => {
    const before = await page.evaluate(() => [document.getElementById('page-range').textContent, performance.now()]);
    await action();
    await page.waitForFunction((text) => document.getElementById('page-range').textContent !== text, before[0], { polling: 5 });
    return (await page.evaluate(() => performance.now())) - before[1];
  };
  const filter = await timeTable(() => page.selectOption('[data-filter-axis="primaries"]', '32'));
  const nextPage = await timeTable(() => page.click('#page-next'));
  await page.close();
  return { load, longest, redraw, filter, nextPage, requests };
}

try {
  await until(() => existsSync(portFile), { what: 'aerobreak serve' });
  const origin = `http://127.0.0.1:${Number(readFileSync(portFile, 'utf8'))}`;
  const fitStart = Date.now();
  const fits = await fetch(`${origin}/api/studies/1/correlations`);
  console.log(`correlations: ${fits.status} in ${((Date.now() - fitStart) / 1000).toFixed(1)} s (fitted once, then stored)`);
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: chromiumArguments });
  const runs = [];
  for (let i = 0; i < Number(runsText); i++) {
    const run = await oneRun(browser, origin);
    runs.push(run);
    console.log(`run ${i + 1}${i === 0 ? ' (cold)' : ''}: page drawn ${run.load.toFixed(0)} ms, longest task ${run.longest.toFixed(0)} ms, ` +
      `outcome redraw ${run.redraw.toFixed(0)} ms, filter ${run.filter.toFixed(0)} ms, next page ${run.nextPage.toFixed(0)} ms; ` +
      `slowest requests: ${run.requests}`);
  }
  // The summary is of the warm runs (all but the first) when there are several.
  const warm = runs.length > 1 ? runs.slice(1) : runs;
  const best = (key) => Math.min(...warm.map((run) => run[key])).toFixed(0);
  const median = (key) => warm.map((run) => run[key]).sort((a, b) => a - b)[Math.floor(warm.length / 2)].toFixed(0);
  console.log(`cold load ${runs[0].load.toFixed(0)} ms; warm runs ${runs.length > 1 ? `2-${runs.length}` : '1'}:`);
  for (const key of ['load', 'longest', 'redraw', 'filter', 'nextPage']) console.log(`${key}: best ${best(key)} ms, median ${median(key)} ms`);
  await browser.close();
} finally {
  server.kill('SIGTERM');
  rmSync(scratch, { recursive: true, force: true });
}
