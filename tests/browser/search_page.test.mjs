// The study page of an adaptive search (docs/ADAPTIVE.md, docs/WEB.md "A study with an adaptive
// search"), in real Chromium against a real service whose worker jobs are the engine's test double
// (tests/support/synthetic_worker.cpp: outcomes from a seeded logistic law of the impact speed,
// every result a copy of one document with its fragments and flags). A search over the impact speed
// per gamma/k_n places its cases at many distinct speeds; its page must show per condition at most
// 6 bins of pooled results as points without a line, each bin's probability and Wilson interval
// those of its pooled counts, the search's own v50 and interval, a fragment-size plot with one
// series per bin and a flagged-results table with one row per bin. A grid study on the same service
// keeps one point per grid point joined by lines, one fragment series per speed and one table row
// per grid point.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { launchBrowser, openPage, Service, smallStudy, withScreenshot } from './support.mjs';

const kBins = 6;
// The share of cases the synthetic worker ends undetermined: left out of each bin's probability, as
// out of the fit and the search.
const kUndeterminedShare = 0.25;
// Every result's fragments (16 primaries, the study's N): one on the wall, three re-entrained.
const kFragments = [[10, true], [3, false], [2, false], [1, false]];
const kResult = {
  outcome: { class: '', fractured_on_wall: true, retained_mass_fraction: 0.625, damage_ratio: 0.25, fragment_count: 4 },
  fragments: { list: kFragments.map(([size, onWall]) => ({ size, mass: size, on_wall: onWall })) },
};

function searchStudy() {
  return {
    name: 'search page', description: 'an adaptive search over the impact speed per gamma/k_n',
    base: {
      cluster: { generator: { method: 'ballistic', primaries: 16 } },
      model: { damping: { law: 'viscoelastic', dissipative_time: 0.05 } },
      run: { time_limit: 20000 },
    },
    axes: { gamma_over_kn: { values: [0.001, 0.004] } },
    search: { axis: 'impact_speed', range: { from: 0.005, to: 0.3 }, relative_width: 0.5, budget: 120, batch: 8,
      initial: 8 },
    replicates: { seed: 7 },
  };
}

let service;
let browser;
let searchId;
let gridId;
let templateDirectory;

test.before(async () => {
  const worker = process.env.AEROBREAK_SYNTHETIC_WORKER;
  assert.ok(worker, 'AEROBREAK_SYNTHETIC_WORKER must name the built synthetic worker');
  templateDirectory = mkdtempSync(path.join(tmpdir(), 'aerobreak-search-page-'));
  const template = path.join(templateDirectory, 'result.json');
  writeFileSync(template, JSON.stringify(kResult));
  service = await Service.start(['--launcher', 'direct', '--worker-program', worker], {
    ranks: 1, environment: { AEROBREAK_SYNTHETIC_RANKS: '4', AEROBREAK_SYNTHETIC_RESULT: template,
      AEROBREAK_SYNTHETIC_UNDETERMINED: String(kUndeterminedShare) } });
  browser = await launchBrowser();
  searchId = await service.submit(searchStudy());
  gridId = await service.submit(smallStudy('grid page', { speeds: [0.02, 0.05, 0.1], primaries: [16],
    gammas: [0.001, 0.004], replicates: 3 }));
  await service.waitComplete(searchId);
  await service.waitComplete(gridId);
});

test.after(async () => {
  await browser?.close();
  await service?.stop();
  if (templateDirectory) rmSync(templateDirectory, { recursive: true, force: true });
});

// What the page shows: each chart's curves with whether uPlot draws a line through them, the
// search's list, the fragment plot's legend and the flagged-results table.
function readView() {
  const chart = (id) => document.getElementById(id);
  const curvesOf = (id) => {
    const u = chart(id).uplot;
    return (chart(id).curves || []).map((curve) => {
      const series = u.series[curve.series[0]];
      const path = series.paths ? series.paths(u, curve.series[0], 0, u.data[0].length - 1) : null;
      return { style: curve.style, label: curve.label, group: curve.group, color: curve.color,
        drawsLine: Boolean(path && path.stroke), points: curve.points.map(({ row, ...point }) => point) };
    });
  };
  const table = chart('flags-table');
  const header = [...table.querySelectorAll('th')].map((node) => node.textContent);
  const resultsColumn = header.indexOf('results');
  return {
    probability: curvesOf('plot-probability'),
    retained: curvesOf('plot-retained'),
    fragments: curvesOf('plot-fragments'),
    fragmentLegend: [...document.querySelectorAll('#plot-fragments .legend li')].map((node) => node.textContent),
    searchList: [...document.querySelectorAll('#search-estimates li')].map((node) => node.textContent),
    flags: { pooled: table.dataset.pooled, rows: Number(table.dataset.rows),
      results: [...table.querySelectorAll('tbody tr')].map((row) => Number(row.children[resultsColumn].textContent)) },
  };
}

async function openStudy(page, id) {
  await page.goto(`${service.origin}/?study=${id}`);
  await page.waitForFunction(() => Number(document.getElementById('plot-probability')?.dataset.fitted) > 0 &&
    document.querySelector('#plot-fragments canvas') && document.getElementById('flags-table').dataset.rows,
  null, { timeout: 60000 });
  return page.evaluate(readView);
}

const sum = (values) => values.reduce((total, value) => total + value, 0);
const speed = 'impact_speed';
const gammaOf = (row) => row.grid_point.gamma_over_kn;

// The grid points of the search's condition gamma/k_n = `gamma` with speeds in [from, to].
const within = (grid, gamma, [from, to] = [-Infinity, Infinity]) => grid.grid_points.filter((row) =>
  gammaOf(row) === gamma && row.grid_point[speed] >= from && row.grid_point[speed] <= to && row.finished > 0);

test('a search study: bins of pooled results as points without a line, and the search\'s v50', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'search page probability', async () => {
    const grid = await service.get(`/api/studies/${searchId}/grid`);
    const search = await service.get(`/api/studies/${searchId}/search`);
    const view = await openStudy(page, searchId);
    const measured = view.probability.filter((curve) => curve.style === 'points');
    assert.equal(measured.length, 2, 'one measured curve per gamma/k_n');
    assert.ok(view.probability.filter((curve) => curve.style === 'fitted').length > 0, 'fitted curves drawn');
    const wilson = await page.evaluate(async (rows) => {
      const { wilsonInterval } = await import('/src/search_bins.js');
      // Stick, bounce and break-up among the determined results, undetermined among all.
      const trials = (row, outcome) => (outcome === 'undetermined' ? row.finished
        : row.finished - row.outcomes.undetermined.count);
      // None where every result is undetermined (the service's ci95 is then null).
      return rows.map((row) => Object.entries(row.outcomes).map(([outcome, each]) => (trials(row, outcome) > 0
        ? wilsonInterval(each.count, trials(row, outcome)) : null)));
    }, grid.grid_points);
    // The page's Wilson interval is the service's at every grid point and outcome.
    grid.grid_points.forEach((row, i) => Object.values(row.outcomes).forEach((each, j) => {
      const same = (a, b) => (a === null ? b === null : Math.abs(a - b) < 1e-12);
      const [lo, hi] = wilson[i][j] || [null, null];
      const [serviceLo, serviceHi] = each.ci95 || [null, null];
      assert.ok(same(lo, serviceLo) && same(hi, serviceHi), `Wilson interval of ${each.count} at ${i}`);
    }));
    for (const [index, gamma] of [0.001, 0.004].entries()) {
      const curve = measured[index];
      assert.ok(curve.label.includes(String(gamma)), curve.label);
      assert.ok(!curve.drawsLine, 'no line joins the bins');
      const speeds = new Set(within(grid, gamma).map((row) => row.grid_point[speed]));
      assert.ok(speeds.size > kBins, `the search ran ${speeds.size} speeds, more than the bins`);
      assert.ok(curve.points.length >= 2 && curve.points.length <= kBins, `${curve.points.length} bins`);
      const finished = sum(within(grid, gamma).map((row) => row.finished));
      assert.equal(sum(curve.points.map((point) => point.results)), finished, 'every result in a bin');
      const undetermined = sum(within(grid, gamma).map((row) => row.outcomes.undetermined.count));
      assert.ok(undetermined > 0 && undetermined < finished, `${undetermined} of ${finished} undetermined`);
      const intervals = await page.evaluate(async (points) => {
        const { wilsonInterval } = await import('/src/search_bins.js');
        return points.map((point) => wilsonInterval(point.count, point.trials));
      }, curve.points);
      curve.points.forEach((point, i) => {
        const rows = within(grid, gamma, point.range);
        assert.equal(point.results, sum(rows.map((row) => row.finished)), `results in ${point.range}`);
        const breakUps = sum(rows.map((row) => row.outcomes['break-up'].count));
        assert.equal(point.count, breakUps, `break-ups in ${point.range}`);
        const undetermined = sum(rows.map((row) => row.outcomes.undetermined.count));
        assert.equal(point.trials, point.results - undetermined, `determined results in ${point.range}`);
        if (point.trials === 0) {
          assert.deepEqual([point.y, point.lo, point.hi], [null, null, null], `no probability in ${point.range}`);
        } else {
          assert.equal(point.y, point.count / point.trials);
          assert.deepEqual([point.lo, point.hi], intervals[i]);
        }
        assert.ok(point.x >= point.range[0] && point.x <= point.range[1], 'a bin sits within its speeds');
        if (i > 0) assert.ok(curve.points[i - 1].range[1] < point.range[0], 'bins do not overlap');
      });
      const group = search.groups.find((each) => each.group.gamma_over_kn === gamma);
      const estimate = group.estimates.find((each) => each.response === 'break-up' && each.level === 0.5);
      const crossing = view.probability.find((each) => each.style === 'crossing' && each.group === curve.group);
      assert.ok(crossing, `the search's v50 at gamma/k_n = ${gamma}`);
      assert.equal(crossing.color, curve.color);
      assert.deepEqual(crossing.points, [{ x: estimate.estimate, y: 0.5, xlo: estimate.lower, xhi: estimate.upper }]);
    }
    assert.equal(view.searchList.length, 2);
    assert.ok(view.searchList.every((line) => /^search: v50 = /.test(line)), view.searchList.join('; '));
    assert.ok(view.retained.every((curve) => !curve.drawsLine), 'means along the searched axis are not joined');
    assert.deepEqual(page.foreignRequests, []);
    assert.deepEqual(page.problems, []);
  });
  await page.context().close();
});

test('a search study: one fragment series and one flagged row per bin', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'search page fragments', async () => {
    const grid = await service.get(`/api/studies/${searchId}/grid`);
    const view = await openStudy(page, searchId);
    const bins = view.probability.filter((curve) => curve.style === 'points');
    // The fragment plot shows the first condition (gamma/k_n = 0.001), in the probability plot's bins.
    assert.equal(view.fragments.length, bins[0].points.length);
    assert.equal(view.fragmentLegend.length, view.fragments.length);
    assert.ok(view.fragmentLegend.length <= kBins, view.fragmentLegend.join('; '));
    const results = view.fragmentLegend.map((text) => Number(/\((\d+) results\)/.exec(text)[1]));
    assert.deepEqual(results, bins[0].points.map((point) => point.results));
    for (const curve of view.fragments) {
      // Every result has one fragment of each size of kFragments: 1 per result and size.
      assert.deepEqual(curve.points.map(({ x, y }) => [x, y]),
        kFragments.map(([size]) => [size, 1]).sort((a, b) => a[0] - b[0]));
    }
    assert.equal(view.flags.pooled, 'true');
    const points = bins.flatMap((curve) => curve.points).length;
    assert.equal(view.flags.rows, points, 'every bin is flagged (every result fractured on the wall)');
    assert.equal(view.flags.results.length, points);
    assert.equal(sum(view.flags.results), sum(grid.grid_points.map((row) => row.finished)));
    assert.deepEqual(page.problems, []);
  });
  await page.context().close();
});

test('a grid study keeps one point per grid point joined by lines', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'grid page beside a search', async () => {
    const view = await openStudy(page, gridId);
    const measured = view.probability.filter((curve) => curve.style === 'measured');
    assert.equal(measured.length, 2);
    assert.ok(measured.every((curve) => curve.drawsLine && curve.points.length === 3));
    assert.equal(view.probability.filter((curve) => curve.style === 'crossing').length, 0);
    assert.deepEqual(view.searchList, []);
    assert.ok(view.retained.every((curve) => curve.drawsLine));
    assert.equal(view.fragments.length, 3, 'one fragment series per speed');
    assert.notEqual(view.flags.pooled, 'true');
    assert.equal(view.flags.rows, 6, 'one flagged row per grid point');
    assert.deepEqual(page.problems, []);
  });
  await page.context().close();
});

// The lookup-table panel's chosen kind, its links' kind and the first metadata record of the CSV it offers.
async function offeredTable(page) {
  await page.locator('#tables-panel a[data-format="csv"]').waitFor();
  const link = page.locator('#tables-panel a[data-format="csv"]');
  const text = await (await fetch(`${service.origin}${await link.getAttribute('href')}`)).text();
  return {
    chosen: await page.locator('#choose-table-kind').inputValue(),
    kinds: await page.locator('#table-links a').evaluateAll((links) => links.map((a) => a.dataset.kind)),
    gridLabel: await page.locator('#choose-table-kind option[value="grid"]').textContent(),
    tableRecord: text.split('\r\n')[1],
  };
}

test('a search study offers the fit table first, a grid study its grid', async () => {
  const page = await openPage(browser, service);
  await openStudy(page, searchId);
  const search = await offeredTable(page);
  assert.equal(search.chosen, 'fit');
  assert.ok(search.kinds.length === 5 && search.kinds.every((kind) => kind === 'fit'), search.kinds.join());
  assert.match(search.tableRecord, /^#table,fit,/, 'the CSV offered is the fit table');
  assert.match(search.gridLabel, /per searched speed/);
  assert.match(await page.locator('#tables-panel .note').textContent(), /the fit table, from the fitted curves/);
  await openStudy(page, gridId);
  const grid = await offeredTable(page);
  assert.equal(grid.chosen, 'grid');
  assert.ok(grid.kinds.every((kind) => kind === 'grid'));
  assert.match(grid.tableRecord, /^#table,grid,/);
  assert.equal(grid.gridLabel, 'grid: per grid point');
  assert.deepEqual(page.problems, []);
  await page.context().close();
});
