// A benchmark, not a test (docs/PERFORMANCE.md, "Dashboard"): times the study page of a store with
// 100,000 results in headless Chromium. Usage, from the repository root after scripts/setup.sh:
//   build/tests/dashboard_store_fill /tmp/big.sqlite   (a new file; once)
//   node tests/bench/web_bench.mjs /tmp/big.sqlite [RUNS]
// (AEROBREAK_BINARY names another aerobreak, AEROBREAK_WEB_DIR another dashboard folder.)
// Prints, per run: the time from navigation to every plot and the case table drawn, the longest
// main-thread task while loading (Long Tasks API), and for each interaction the time from the
// input event until the page shows its answer and the browser has painted it (the next animation
// frame): another outcome chosen (its measured curves drawn; then its fitted curves), the case
// table filtered (N = 32) and its page turned, with the longest task while they ran; and the
// requests of the load that took longest (Resource Timing: from the request's start to its last
// byte). The first run after the service starts is the cold one: the service then computes the
// grid statistics it keeps until the study changes. The correlations are fitted (and stored) once
// before the runs, since the page asks for them after it is drawn and a first fit of 100,000
// results would weigh on the runs after it.
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
const webDirectory = process.env.AEROBREAK_WEB_DIR ? ['--web-dir', process.env.AEROBREAK_WEB_DIR] : [];
const server = spawn(binary, ['serve', '--store', store, '--data', scratch, '--port', '0', '--port-file', portFile,
  '--ranks', '1',
  ...webDirectory], { stdio: 'ignore' });

function drawn() {
  const charts = ['plot-probability', 'plot-critical', 'plot-retained', 'plot-damage', 'plot-restitution',
    'plot-fragments'];
  return charts.every((id) => document.getElementById(id)?.dataset.series !== undefined) &&
    document.querySelector('#case-table table') !== null;
}

// In the page: does one interaction (`kind`: choose the outcome `value`, wait for its fits, filter
// the case table on N = `value`, turn the page), then waits, polling each frame, until the page
// shows the answer, then for the next frame to be painted; returns the milliseconds from the input
// and the longest task meanwhile.
function interaction(page, kind, value) {
  return page.evaluate(async ({ kind, value }) => {
    const frame = () => new Promise((resolve) => requestAnimationFrame(() => setTimeout(resolve, 0)));
    const chart = document.getElementById('plot-probability');
    const range = () => document.getElementById('page-range').textContent;
    const rangeBefore = range();
    const shows = (outcome) => chart.dataset.outcome === undefined || chart.dataset.outcome === outcome;
    const done = {
      outcome: () => chart.uplot && chart.curves.length > 0 && chart.curves.every((curve) => !curve.fit) &&
        shows(value),
      fits: () => Number(chart.dataset.fitted || 0) > 0 && shows(value),
      filter: () => range() !== rangeBefore,
      next: () => range() !== rangeBefore,
    }[kind];
    performance.mark(`${kind}-start`);
    const start = performance.now();
    if (kind === 'outcome' || kind === 'filter') {
      const control = document.querySelector(kind === 'outcome' ? '#choose-outcome' : '[data-filter-axis="primaries"]');
      control.value = value;
      control.dispatchEvent(new Event('change'));
    } else if (kind === 'next') {
      document.getElementById('page-next').click();
    }
    while (!done()) {
      await frame();
      if (performance.now() - start > 60000) throw new Error(`${kind}: no answer within 60 s`);
    }
    await frame();
    const end = performance.now();
    performance.mark(`${kind}-end`);
    const longest = Math.max(0, ...window.longTasks.filter(([at]) => at >= start - 1).map(([, duration]) => duration));
    return { ms: end - start, longest };
  }, { kind, value });
}

// A main-thread task in Chromium's trace (its name differs between versions); promise
// continuations (after a fetch, say) run as a microtask checkpoint of their own.
const kTaskEvents = ['RunTask', 'ThreadControllerImpl::RunTask', 'BlinkScheduler_PerformMicrotaskCheckpoint'];

// The events that no other of them contains, in time order.
function outermost(events) {
  const kept = [];
  for (const event of [...events].sort((a, b) => a.ts - b.ts || b.dur - a.dur)) {
    const last = kept[kept.length - 1];
    if (!last || event.ts >= last.ts + last.dur) kept.push(event);
  }
  return kept;
}

// The page's main-thread tasks (trace events of tasks of the renderer thread that made the marks)
// between two marks, or from the thread's first task to a mark: the longest one's thread CPU time
// and the CPU time of all together (ms). Wall times on a loaded machine include the time the
// thread waited for a core; CPU times are the page's own work.
function cpuBetween(trace, startMark, endMark) {
  const events = trace.traceEvents;
  const mark = (name) => events.find((event) => event.name === name && event.cat.includes('blink.user_timing'));
  const end = mark(endMark);
  const tasks = outermost(events.filter((event) => kTaskEvents.includes(event.name) && event.ph === 'X' &&
    event.pid === end.pid &&
    event.tid === end.tid && typeof event.tdur === 'number'));
  const from = startMark ? mark(startMark).ts : Math.min(...tasks.map((task) => task.ts));
  const inside = tasks.filter((task) => task.ts + task.dur >= from && task.ts <= end.ts);
  return { longest: Math.max(0, ...inside.map((task) => task.tdur)) / 1000, total: inside.reduce((sum,
    task) => sum + task.tdur, 0) / 1000 };
}

async function oneRun(browser, origin) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 900 } });
  await browser.startTracing(page, { categories: ['toplevel', 'blink.user_timing'] });
  await page.addInitScript(() => {
    window.longTasks = [];
    new PerformanceObserver((list) => window.longTasks.push(...list.getEntries().map((e) => [e.startTime, e.duration])))
      .observe({ type: 'longtask', buffered: true });
  });
  await page.goto(`${origin}/?study=1`);
  await page.waitForFunction(drawn, null, { timeout: 60000, polling: 10 });
  const load = await page.evaluate(() => {
    performance.mark('load-end');
    return performance.now();
  });
  const longest = await page.evaluate(() => Math.max(0, ...window.longTasks.map(([, duration]) => duration)));
  const requests = await page.evaluate(() => performance.getEntriesByType('resource')
    .filter((entry) => entry.name.includes('/api/')).sort((a, b) => b.duration - a.duration).slice(0, 3)
    .map((entry) => `${new URL(entry.name).pathname} ${entry.duration.toFixed(0)} ms`).join(', '));
  // The fits of the first outcome arrive after the page is drawn; the interactions start after.
  await page.waitForFunction(() => Number(document.getElementById('plot-probability').dataset.fitted || 0) > 0,
    null, { timeout: 60000, polling: 50 });
  await page.waitForTimeout(500);
  const outcome = await interaction(page, 'outcome', 'stick');
  const fits = await interaction(page, 'fits', 'stick');
  const filter = await interaction(page, 'filter', '32');
  const nextPage = await interaction(page, 'next');
  const trace = JSON.parse(await browser.stopTracing());
  await page.close();
  const cpu = Object.fromEntries([['load', null, 'load-end'], ...['outcome', 'fits', 'filter', 'next'].map((k) => [k,
    `${k}-start`, `${k}-end`])]
    .map(([key, start, end]) => [key, cpuBetween(trace, start, end)]));
  return { load, longest, redraw: outcome.ms, fits: outcome.ms + fits.ms, filter: filter.ms, nextPage: nextPage.ms,
    interactionTask: Math.max(outcome.longest, fits.longest, filter.longest, nextPage.longest), requests,
    cpuLoadLongest: cpu.load.longest, cpuLoad: cpu.load.total,
    cpuInteractionLongest: Math.max(cpu.outcome.longest, cpu.fits.longest, cpu.filter.longest, cpu.next.longest),
    cpuRedraw: cpu.outcome.total, cpuFits: cpu.fits.total, cpuFilter: cpu.filter.total, cpuNextPage: cpu.next.total };
}

try {
  await until(() => existsSync(portFile), { what: 'aerobreak serve' });
  const origin = `http://127.0.0.1:${Number(readFileSync(portFile, 'utf8'))}`;
  const fitStart = Date.now();
  const fits = await fetch(`${origin}/api/studies/1/correlations`);
  const seconds = ((Date.now() - fitStart) / 1000).toFixed(1);
  console.log(`correlations: ${fits.status} in ${seconds} s (fitted once, then stored)`);
  const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: chromiumArguments });
  const runs = [];
  for (let i = 0; i < Number(runsText); i++) {
    const run = await oneRun(browser, origin);
    runs.push(run);
    const ms = (key) => `${run[key].toFixed(0)} ms`;
    console.log(`run ${i + 1}${i === 0 ? ' (cold)' : ''}: page drawn ${ms('load')}, longest task ${ms('longest')}; ` +
      `another outcome: measured ${ms('redraw')}, fitted ${ms('fits')}; filter ${ms('filter')}, ` +
      `next page ${ms('nextPage')}; longest task in these ${ms('interactionTask')}; slowest requests: ${run.requests}`);
    console.log(`  main-thread CPU: load ${ms('cpuLoad')} (longest task ${ms('cpuLoadLongest')}); another outcome ` +
      `${ms('cpuRedraw')}, its fits ${ms('cpuFits')}, filter ${ms('cpuFilter')}, next page ` +
      `${ms('cpuNextPage')} (longest task ${ms('cpuInteractionLongest')})`);
  }
  // The summary is of the warm runs (all but the first) when there are several.
  const warm = runs.length > 1 ? runs.slice(1) : runs;
  const best = (key) => Math.min(...warm.map((run) => run[key])).toFixed(0);
  const median = (key) => warm.map((run) => run[key]).sort((a, b) => a - b)[Math.floor(warm.length / 2)].toFixed(0);
  console.log(`cold load ${runs[0].load.toFixed(0)} ms; warm runs ${runs.length > 1 ? `2-${runs.length}` : '1'}:`);
  for (const key of ['load', 'longest', 'redraw', 'fits', 'filter', 'nextPage', 'interactionTask', 'cpuLoad',
    'cpuLoadLongest',
    'cpuRedraw', 'cpuFits', 'cpuFilter', 'cpuNextPage', 'cpuInteractionLongest'])
    console.log(`${key}: best ${best(key)} ms, median ${median(key)} ms`);
  await browser.close();
} finally {
  server.kill('SIGTERM');
  rmSync(scratch, { recursive: true, force: true });
}
