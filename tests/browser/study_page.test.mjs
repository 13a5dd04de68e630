// A finished study's page in real Chromium: the plots hold the server's numbers (series and points
// counted in the charts' own data), a plot choice and the case-table filters survive as a permalink,
// a filter narrows the table, paging works, and a case's page offers its H5MD file for download.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { Service, launchBrowser, openPage, smallStudy, withScreenshot } from './support.mjs';

const kSpeeds = [0.005, 0.03, 0.3];
let service;
let browser;
let studyId;
let grid;

before(async () => {
  service = await Service.start();
  browser = await launchBrowser();
  // 3 speeds x N 8, 16 x gamma/k_n 0.001, 0.01 x 3 replicates = 36 cases.
  studyId = await service.submit(smallStudy('plots', { speeds: kSpeeds, replicates: 3 }));
  await service.waitComplete(studyId);
  grid = await service.get(`/api/studies/${studyId}/grid`);
});

after(async () => {
  await browser?.close();
  await service?.stop();
});

// What a chart holds: its curves (label, points) and, from uPlot's own data, the non-null values of
// each series.
function chartContents(page, id) {
  return page.evaluate((chartId) => {
    const chart = document.getElementById(chartId);
    const u = chart.uplot;
    return {
      curves: chart.curves.map((curve) => ({ label: curve.label, dashed: Boolean(curve.dashed), points: curve.points.map((p) => [p.x, p.y]) })),
      seriesLabels: u ? u.series.slice(1).map((s) => s.label) : [],
      nonNull: u ? u.data.slice(1).map((column) => column.filter((v) => v !== null).length) : [],
      legend: chart.querySelectorAll('.legend li').length,
    };
  }, id);
}

async function openStudy(page, search = '') {
  await page.goto(`${service.origin}/?study=${studyId}${search}`);
  await page.locator('#case-table table').waitFor();
  await page.waitForFunction(() => document.getElementById('plot-fragments').dataset.series !== undefined);
}

// Server-side numbers for one outcome: {label-free key 'N,gamma' -> [[speed, probability]...]}.
function probabilities(outcome) {
  const curves = {};
  for (const row of grid.grid_points) {
    const key = `${row.grid_point.primaries},${row.grid_point.gamma_over_kn}`;
    (curves[key] ||= []).push([row.grid_point.impact_speed, row.outcomes[outcome].probability]);
  }
  return Object.values(curves).map((points) => points.sort((a, b) => a[0] - b[0]));
}

// The per-group logistic fits of P in log impact speed that the page draws (docs/CORRELATIONS.md).
async function speedFits(outcome) {
  const summary = await service.get(`/api/studies/${studyId}/correlations`);
  return summary.fits.filter((fit) => fit.kind === 'logistic' && fit.dose === 'impact_speed' &&
    (!outcome || fit.response === outcome) && Object.keys(fit.group).length > 0 && fit.coefficients.length === 2);
}

const sortedPoints = (curves) => curves.map((c) => c.points).sort((a, b) => JSON.stringify(a).localeCompare(JSON.stringify(b)));

test('the plots hold one curve per N and gamma/k_n with a point per speed, and the server numbers', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'study-plots', async () => {
    await openStudy(page);
    const probability = await chartContents(page, 'plot-probability');
    const fits = await speedFits('break-up');
    assert.ok(fits.length >= 1, 'break-up is fitted in at least one group');
    assert.equal(probability.curves.length, 4 + fits.length);
    assert.equal(probability.legend, 4 + fits.length);
    // Each measured curve: its probability and the two bounds of its band, 3 values each; each
    // fitted curve (dashed): 25 points over its fit's validity box.
    assert.equal(probability.seriesLabels.length, 12 + fits.length);
    assert.deepEqual(probability.nonNull, [...Array(12).fill(3), ...Array(fits.length).fill(25)]);
    const measured = probability.curves.filter((curve) => !curve.dashed);
    assert.deepEqual(sortedPoints(measured), sortedPoints(probabilities('break-up').map((points) => ({ points }))));
    // The fitted curves are the fits' logistic(b0 + b1 ln v), from the slowest speed to the fastest.
    const logistic = (eta) => 1 / (1 + Math.exp(-eta));
    const ends = (points) => [points[0], points[points.length - 1]];
    const drawn = probability.curves.filter((curve) => curve.dashed).map((curve) => ends(curve.points));
    const expected = fits.map((fit) => ends([fit.validity.impact_speed.min, fit.validity.impact_speed.max]
      .map((v) => [v, logistic(fit.coefficients[0] + fit.coefficients[1] * Math.log(v))])));
    const byValue = (a, b) => a[0][1] - b[0][1] || a[1][1] - b[1][1];
    drawn.sort(byValue);
    expected.sort(byValue);
    drawn.forEach((pair, i) => pair.forEach((point, k) => {
      assert.ok(Math.abs(point[0] / expected[i][k][0] - 1) < 1e-12, 'speed');
      assert.ok(Math.abs(point[1] - expected[i][k][1]) < 1e-12, 'probability');
    }));

    for (const id of ['plot-retained', 'plot-restitution']) {
      const chart = await chartContents(page, id);
      assert.equal(chart.curves.length, 4, id);
      assert.ok(chart.curves.every((curve) => curve.points.length === 3), id);
    }
    const retained = (await chartContents(page, 'plot-retained')).curves.flatMap((c) => c.points.map((p) => p[1]));
    assert.ok(retained.every((value) => value >= 0 && value <= 1));

    // Critical speed: one point per curve whose measured probability crosses 0.5, at its N.
    const crossing = probabilities('break-up').filter((points) =>
      points.some(([, p], i) => i > 0 && (points[i - 1][1] - 0.5) * (p - 0.5) <= 0 && points[i - 1][1] !== p));
    const critical = await chartContents(page, 'plot-critical');
    const measuredCritical = critical.curves.filter((curve) => !curve.label.startsWith('fitted'));
    assert.equal(measuredCritical.flatMap((c) => c.points).length, crossing.length);
    assert.ok(crossing.length >= 1, 'break-up takes over somewhere between 0.005 and 0.3 d/tau');
    // Fitted critical speeds: a point per fit and level with an estimate, at the fit's N.
    const fittedCritical = critical.curves.filter((curve) => curve.label.startsWith('fitted')).flatMap((c) => c.points);
    const estimates = fits.flatMap((fit) => fit.critical.filter((value) => typeof value.estimate === 'number')
      .map((value) => [fit.group.primaries, value.estimate]));
    assert.deepEqual(fittedCritical.sort(), estimates.sort());
    for (const [n, speed] of measuredCritical.flatMap((c) => c.points)) {
      assert.ok([8, 16].includes(n));
      assert.ok(speed > kSpeeds[0] && speed < kSpeeds[2]);
    }

    // Fragment sizes of the first curve (N = 8, gamma/k_n = 0.001): a series per speed, a point per size.
    const sizes = await service.get(`/api/studies/${studyId}/fragment-sizes?axis.primaries=8&axis.gamma_over_kn=0.001`);
    const fragments = await chartContents(page, 'plot-fragments');
    assert.equal(fragments.curves.length, sizes.grid_points.length);
    assert.deepEqual(fragments.curves.map((c) => c.points.length), sizes.grid_points.map((p) => p.sizes.length));
    assert.deepEqual(page.foreignRequests, []);
    assert.deepEqual(page.problems, []);
  });
});

test('a plot choice is a permalink: the URL reproduces it', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'study-permalink', async () => {
    await openStudy(page);
    await page.selectOption('#choose-outcome', 'stick');
    await page.waitForURL(/outcome=stick/);
    const url = page.url();
    const again = await openPage(browser, service);
    await again.goto(url);
    await again.locator('#case-table table').waitFor();
    assert.equal(await again.inputValue('#choose-outcome'), 'stick');
    const probability = await chartContents(again, 'plot-probability');
    const measured = probability.curves.filter((curve) => !curve.dashed);
    assert.deepEqual(sortedPoints(measured), sortedPoints(probabilities('stick').map((points) => ({ points }))));
    assert.equal(probability.curves.length - measured.length, (await speedFits('stick')).length);
  });
});

test('filters narrow the case table, paging walks it, and both are kept in the URL', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'study-case-table', async () => {
    await openStudy(page);
    assert.equal(await page.locator('#page-range').textContent(), '1–25 of 36');
    await page.click('#page-next');
    await page.waitForFunction(() => document.getElementById('page-range').textContent === '26–36 of 36');
    assert.equal(await page.locator('#case-table tbody tr').count(), 11);

    await page.selectOption('[data-filter-axis="primaries"]', '8');
    await page.waitForFunction(() => document.getElementById('page-range').textContent === '1–18 of 18');
    const expected = await service.get(`/api/studies/${studyId}/case-table?axis.primaries=8&outcome=stick`);
    await page.selectOption('#filter-outcome', 'stick');
    await page.waitForFunction((total) => document.getElementById('case-table').dataset.total === String(total), expected.total);
    const rows = page.locator('#case-table tbody tr');
    assert.equal(await rows.count(), Math.min(25, expected.total));
    assert.ok(expected.total < 18, 'the outcome filter narrows further');
    for (const row of await rows.all()) {
      const cells = await row.locator('td').allTextContents();
      assert.equal(cells[3], '8');   // Case, v, gamma/k_n, N, ...
      assert.equal(cells[6], 'stick');
    }
    assert.match(page.url(), /f\.axis\.primaries=8/);
    const again = await openPage(browser, service);
    await again.goto(page.url());
    await again.waitForFunction((total) => document.getElementById('case-table')?.dataset.total === String(total), expected.total);
    assert.equal(await again.inputValue('#filter-outcome'), 'stick');
  });
});

test("a case's page shows its fragments and attempts and downloads its H5MD file; absent services hide their panels", async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'case-page', async () => {
    await openStudy(page);
    // The export service is absent (404): no tables panel; the correlations list every speed fit.
    assert.equal(await page.locator('#tables-panel').count(), 0);
    assert.equal(await page.locator('#panel-correlations tbody tr').count(), (await speedFits()).length);
    const caseId = Number(await page.locator('#case-table tbody tr').last().locator('a').textContent());
    await page.locator('#case-table tbody tr').last().locator('a').click();
    await page.locator('#case-title').waitFor();
    const detail = await service.get(`/api/cases/${caseId}`);
    assert.equal(await page.locator('#fragments-table tbody tr').count(), detail.fragments.length);
    assert.equal(await page.locator('#attempts-table tbody tr').count(), detail.attempt_history.length);
    assert.ok(await page.locator('#energy-shares tbody tr').count() >= 5);
    const outcomeText = await page.locator('#outcome').textContent();
    assert.match(outcomeText, new RegExp(`class${detail.result.outcome.class}`));
    assert.doesNotMatch(await page.locator('#view').textContent(), /\[object /, 'every value shown as text, none as an object');
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download-h5')]);
    const file = await download.path();
    const bytes = readFileSync(file);
    assert.deepEqual([...bytes.subarray(0, 8)], [0x89, 0x48, 0x44, 0x46, 0x0d, 0x0a, 0x1a, 0x0a], 'an HDF5 file');
    assert.equal(download.suggestedFilename(), `case-${caseId}.h5`);
    assert.deepEqual(page.foreignRequests, []);
    assert.deepEqual(page.problems, []);
  });
});
