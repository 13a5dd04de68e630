// A finished study's page in real Chromium: the plots hold the server's numbers (series and points
// counted in the charts' own data), a plot choice and the case-table filters survive as a permalink,
// a filter narrows the table, paging works; the outcome fields (damage ratio, flags, energy per
// contact) are shown; the correlation service's fits are drawn over the points; a lookup table
// downloads; and a case's page shows its outcome and offers its H5MD file for download.
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

// What a chart holds: its curves (label, style, points), from uPlot's own data the non-null values
// of each series, the whiskers drawn (clipped intervals), the scales' ranges, the ticks and labels
// of each axis as the chart's options make them, the width of the y label against the plot's
// height, and the legend's entries with their swatch styles.
function chartContents(page, id) {
  return page.evaluate((chartId) => {
    const chart = document.getElementById(chartId);
    const u = chart.uplot;
    const axis = (i) => {
      if (!u) return null;
      const scale = u.scales[i === 0 ? 'x' : 'y'];
      const ticks = u.axes[i].splits ? u.axes[i].splits(u, i, scale.min, scale.max) : [];
      return { label: u.axes[i].label, ticks, tickLabels: u.axes[i].values(u, ticks), range: [scale.min, scale.max] };
    };
    const labelWidth = () => {
      const context = document.createElement('canvas').getContext('2d');
      context.font = u.axes[1].labelFont[0];
      return context.measureText(u.axes[1].label).width;
    };
    return {
      curves: chart.curves.map((curve) => ({ label: curve.label, fit: curve.fit, style: curve.style,
        points: curve.points.map((p) => [p.x, p.y]), band: curve.points.map((p) => [p.lo, p.hi]) })),
      seriesLabels: u ? u.series.slice(1).map((s) => s.label) : [],
      nonNull: u ? u.data.slice(1).map((column) => column.filter((v) => v !== null).length) : [],
      whiskers: (chart.whiskers || []).map((w) => ({ label: w.label, lo: w.lo.filter((v) => v !== null),
        hi: w.hi.filter((v) => v !== null) })),
      x: axis(0), y: axis(1), yLabelWidth: u ? labelWidth() : 0, plotHeight: u ? u.bbox.height / devicePixelRatio : 0,
      legend: [...chart.querySelectorAll('.legend li')].map((li) => ({ text: li.textContent, group: li.dataset.group,
        swatch: li.querySelector('.swatch').className })),
    };
  }, id);
}

// Every whisker of a chart lies within [low, high].
const whiskersWithin = (chart, [low, high]) => chart.whiskers.every((w) => [...w.lo,
  ...w.hi].every((v) => v >= low && v <= high));

async function openStudy(page, search = '') {
  await page.goto(`${service.origin}/?study=${studyId}${search}`);
  await page.locator('#case-table table').waitFor();
  await page.waitForFunction(() => document.getElementById('plot-fragments').dataset.series !== undefined);
}

// Server-side numbers, one curve per N and gamma/k_n: [[speed, valueOf(row)]...] sorted by speed.
function serverCurves(valueOf) {
  const curves = {};
  for (const row of grid.grid_points) {
    const key = `${row.grid_point.primaries},${row.grid_point.gamma_over_kn}`;
    (curves[key] ||= []).push([row.grid_point.impact_speed, valueOf(row)]);
  }
  return Object.values(curves).map((points) => points.sort((a, b) => a[0] - b[0]));
}

const probabilities = (outcome) => serverCurves((row) => row.outcomes[outcome].probability);

// The measured curves of a chart: neither a fit nor the small-strain rings.
const measuredCurves = (chart) => chart.curves.filter((curve) => !curve.fit && !curve.label.startsWith('outside'));
const sortedPoints = (curves) => curves.map((c) => c.points)
  .sort((a, b) => JSON.stringify(a).localeCompare(JSON.stringify(b)));

test('the plots hold one curve per N and gamma/k_n with a point per speed, and the server numbers', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'study-plots', async () => {
    await openStudy(page);
    const probability = await chartContents(page, 'plot-probability');
    // The measured curves come first; the fitted ones and the small-strain rings (tested below) after.
    const measured = measuredCurves(probability);
    assert.equal(measured.length, 4);
    assert.ok(probability.legend.length >= 4);
    // Each measured curve: one series of 3 points, its Wilson intervals as whiskers (not bands).
    assert.equal(probability.seriesLabels.filter((label) => !/\(fit|^outside/.test(label)).length, 4);
    assert.deepEqual(probability.nonNull.slice(0, 4), Array(4).fill(3));
    assert.deepEqual(sortedPoints(measured), sortedPoints(probabilities('break-up').map((points) => ({ points }))));
    assert.equal(probability.whiskers.length, 4);
    const wilson = serverCurves((row) => row.outcomes['break-up'].ci95).flat().map(([, ci]) => ci);
    assert.deepEqual(probability.whiskers.flatMap((w) => w.lo.map((lo, i) => [lo, w.hi[i]])).sort(), wilson.sort());
    // The legend: a key of the kinds (measured with whiskers), then one entry per group.
    assert.deepEqual(probability.legend.filter((entry) => /\bmeasured\b/.test(entry.swatch)).map((entry) => entry.text),
      ['measured, whiskers: 95 % interval']);
    assert.equal(probability.legend.filter((entry) => entry.group !== undefined).length, 4);

    // A click on a legend entry hides its series, another shows it again.
    const shown = () => page.evaluate(() => document.getElementById('plot-probability').uplot.series[1].show);
    const firstGroup = page.locator('#plot-probability .legend li[data-group]').first();
    await firstGroup.click();
    assert.equal(await shown(), false);
    await firstGroup.click();
    assert.equal(await shown(), true);

    // Every plot along the speed spans the tested speeds, not whole decades, with a tick at each
    // (the restitution's, which has no point in this study without bounces, is tested below).
    for (const id of ['plot-probability', 'plot-retained', 'plot-damage']) {
      const chart = await chartContents(page, id);
      const [low, high] = chart.x.range;
      assert.ok(low < kSpeeds[0] && low > kSpeeds[0] / 1.3 && high > kSpeeds[2] && high < kSpeeds[2] * 1.3,
        `${id}: ${low}-${high}`);
      assert.deepEqual(chart.x.ticks, kSpeeds, id);
      assert.ok(chart.yLabelWidth <= chart.plotHeight, `${id}: the y label fits`);
    }
    // Bounded quantities: the axis keeps [0, 1] and the intervals are cut to it.
    for (const id of ['plot-probability', 'plot-retained', 'plot-damage']) {
      const chart = await chartContents(page, id);
      assert.ok(chart.y.range[0] >= -0.05 && chart.y.range[0] < 0 && chart.y.range[1] > 1 && chart.y.range[1] <= 1.05,
        id);
      assert.ok(whiskersWithin(chart, [0, 1]), id);
    }

    const retainedChart = await chartContents(page, 'plot-retained');
    assert.equal(retainedChart.curves.length, 4);
    assert.ok(retainedChart.curves.every((curve) => curve.points.length === 3));
    // Restitution: the bounces' only, a point where a grid point has bounces.
    const restitution = await chartContents(page, 'plot-restitution');
    const bounced = grid.grid_points.filter((row) => row.restitution && row.restitution.n > 0).length;
    assert.equal(restitution.curves.flatMap((c) => c.points).length, bounced);
    if (bounced === 0) {
      assert.match(await page.locator('#plot-restitution').innerText(), /no case here bounced/);
      // The panel holds its message only, not the height of a plot beside it.
      const [restitutionHeight, fragmentsHeight] = await page.evaluate(() => ['panel-restitution', 'panel-fragments']
        .map((id) => document.getElementById(id).getBoundingClientRect().height));
      assert.ok(restitutionHeight < fragmentsHeight / 2, `restitution ${restitutionHeight} px, ${fragmentsHeight} px`);
    }
    const retained = (await chartContents(page, 'plot-retained')).curves.flatMap((c) => c.points.map((p) => p[1]));
    assert.ok(retained.every((value) => value >= 0 && value <= 1));

    // Critical speed: one point per curve whose measured probability crosses 0.5, at its N, as the
    // service computes it (observed_crossings; drawn once the correlations have arrived).
    const crossing = probabilities('break-up').filter((points) =>
      points.some(([, p], i) => i > 0 && (points[i - 1][1] - 0.5) * (p - 0.5) <= 0 && points[i - 1][1] !== p));
    await page.waitForFunction(() => Number(document.getElementById('plot-critical').dataset.fitted) > 0, null,
      { timeout: 60000 });
    const critical = await chartContents(page, 'plot-critical');
    const measuredCritical = critical.curves.filter((curve) => !curve.label.startsWith('fitted'));
    assert.equal(measuredCritical.flatMap((c) => c.points).length, crossing.length);
    // N has a tick and a label at each size; the y label fits beside the plot.
    assert.deepEqual(critical.x.ticks, [8, 16]);
    assert.deepEqual(critical.x.tickLabels, ['8', '16']);
    assert.equal(critical.y.label, 'critical speed (d/τ)');
    assert.ok(critical.yLabelWidth <= critical.plotHeight, 'the y label fits');
    assert.ok(crossing.length >= 1, 'break-up takes over somewhere between 0.005 and 0.3 d/tau');
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
    assert.deepEqual(sortedPoints(measuredCurves(probability)),
      sortedPoints(probabilities('stick').map((points) => ({ points }))));
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
    await page.waitForFunction((total) => document.getElementById('case-table').dataset.total === String(total),
      expected.total);
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
    await again.waitForFunction((total) => document.getElementById('case-table')?.dataset.total === String(total),
      expected.total);
    assert.equal(await again.inputValue('#filter-outcome'), 'stick');
  });
});

test("a case's page shows its outcome, validity, energy groups, fragments and attempts and downloads its H5MD file",
  async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'case-page', async () => {
    await openStudy(page);
    const row = page.locator('#case-table tbody tr').last();
    const caseId = Number(await row.locator('a').textContent());
    const listed = (await service.get(`/api/studies/${studyId}/case-table?limit=36`)).items
      .find((c) => c.id === caseId);
    const flags = [listed.fractured_on_wall && 'fractured on wall',
      listed.small_strain_exceeded && 'small strain exceeded'].filter(Boolean);
    assert.equal((await row.locator('td.flags').textContent()), flags.join(', '));
    await row.locator('a').click();
    await page.locator('#case-title').waitFor();
    const detail = await service.get(`/api/cases/${caseId}`);
    const { outcome, validity, dimensionless } = detail.result;
    assert.equal(await page.locator('#fragments-table tbody tr').count(), detail.fragments.length);
    assert.equal(await page.locator('#attempts-table tbody tr').count(), detail.attempt_history.length);
    assert.ok(await page.locator('#energy-shares tbody tr').count() >= 5);
    assert.equal(await page.locator('#outcome-class').textContent(), outcome.class);
    const outcomeFacts = await facts(page, '#outcome-facts');
    assert.equal(outcomeFacts['fractured on the wall'], outcome.fractured_on_wall ? 'yes' : 'no');
    assert.equal(Number(outcomeFacts['retained mass fraction']), Number(outcome.retained_mass_fraction.toPrecision(4)));
    assert.equal(Number(outcomeFacts['re-entrained mass fraction']),
      Number(outcome.reentrained_mass_fraction.toPrecision(4)));
    const reentrained = page.locator('#reentrained-table tbody tr');
    assert.equal(await reentrained.count(), outcome.reentrained_fragments.length);
    for (const [i, fragment] of outcome.reentrained_fragments.entries())
      assert.equal(Number(await reentrained.nth(i).locator('td').first().textContent()), fragment.primaries);
    assert.match(await page.locator('#validity-verdict').textContent(), validity.small_strain ? /^Within/ : /^Outside/);
    const groups = await facts(page, '#energy-groups-facts');
    assert.equal(Number(groups['E_kin / (N_c E_break)']), Number(dimensionless.energy_per_contact.toPrecision(4)));
    assert.equal(Number(groups['N_c, initial contacts']), dimensionless.initial_contacts);
    assert.doesNotMatch(await page.locator('#view').textContent(), /\[object /,
      'every value shown as text, none as an object');
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#download-h5')]);
    const bytes = readFileSync(await download.path());
    assert.deepEqual([...bytes.subarray(0, 8)], [0x89, 0x48, 0x44, 0x46, 0x0d, 0x0a, 0x1a, 0x0a], 'an HDF5 file');
    assert.equal(download.suggestedFilename(), `case-${caseId}.h5`);
    assert.deepEqual(page.foreignRequests, []);
    assert.deepEqual(page.problems, []);
  });
});

test('the outcome fields: damage ratio plot, flagged results, energy per contact along x', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'study-outcome-fields', async () => {
    await openStudy(page);
    const damage = await chartContents(page, 'plot-damage');
    assert.deepEqual(sortedPoints(damage.curves),
      sortedPoints(serverCurves((row) => row.damage_ratio?.mean).map((points) => ({ points }))));
    assert.equal(damage.curves.flatMap((c) => c.points).length, 12);

    const summary = await page.locator('#flags-summary').evaluate((node) => ({ ...node.dataset }));
    for (const flag of ['fractured_on_wall', 'small_strain_exceeded', 'small_strain_unchecked'])
      assert.equal(Number(summary[flag]), grid.grid_points.reduce((sum, row) => sum + row[flag], 0), flag);
    const flaggedRows = grid.grid_points.filter((row) =>
      row.fractured_on_wall + row.small_strain_exceeded + row.small_strain_unchecked > 0);
    assert.equal(Number(await page.locator('#flags-table').getAttribute('data-rows')), flaggedRows.length);
    const probability = await chartContents(page, 'plot-probability');
    const rings = probability.curves.filter((curve) => curve.label.startsWith('outside the small-strain range'));
    const exceeded = grid.grid_points.filter((row) => row.small_strain_exceeded > 0);
    assert.equal(rings.length, exceeded.length > 0 ? 1 : 0);
    assert.equal(rings.flatMap((curve) => curve.points).length, exceeded.length);

    await page.selectOption('#choose-x', 'energy_per_contact');
    await page.waitForURL(/x=energy_per_contact/);
    await page.waitForFunction(() => document.getElementById('plot-probability').curves.length > 0);
    const alongEnergy = await chartContents(page, 'plot-probability');
    const expected = {};
    for (const row of grid.grid_points)
      (expected[`${row.grid_point.primaries},${row.grid_point.gamma_over_kn}`] ||= [])
        .push([row.energy_per_contact.mean, row.outcomes['break-up'].probability]);
    const measured = measuredCurves(alongEnergy);
    assert.deepEqual(sortedPoints(measured),
      sortedPoints(Object.values(expected).map((points) => ({ points: points.sort((a, b) => a[0] - b[0]) }))));
    assert.deepEqual(page.problems, []);
  });
});

test('the correlations service: fitted curves with bands over the points, critical speeds against N, their table',
  async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'study-correlations', async () => {
    await openStudy(page);
    const summary = await service.get(`/api/studies/${studyId}/correlations`);
    const groupFits = summary.fits.filter((fit) => fit.kind === 'logistic' && fit.response === 'break-up' &&
      fit.dose === 'impact_speed' && fit.pooled_over.length === 0);
    assert.equal(groupFits.length, 4, 'one fit per N and gamma/k_n');
    const documents = await Promise.all(groupFits.map((fit) =>
      service.get(`/api/studies/${studyId}/correlations/${fit.name}`)));
    const withCurves = documents.filter((document) => document.curves.length > 0);
    assert.ok(withCurves.length >= 1, 'some group has a fitted curve');
    await page.waitForFunction((n) => document.getElementById('plot-probability').dataset.fitted === String(n),
      withCurves.length, { timeout: 60000 });
    const probability = await chartContents(page, 'plot-probability');
    const fitted = probability.curves.filter((curve) => curve.label.endsWith('(fit)'));
    assert.equal(fitted.length, withCurves.length);
    for (const document of withCurves) {
      const drawn = probability.curves.find((curve) => curve.fit === document.name);
      assert.ok(drawn, document.name);
      assert.deepEqual(drawn.points, document.curves[0].points.map((point) => [point.dose, point.value]));
      assert.deepEqual(drawn.band, document.curves[0].points.map((point) => point.ci95));
      const measured = probability.curves.find((curve) => curve.label === drawn.label.replace(' (fit)', ''));
      assert.ok(measured && measured.points.length === 3, 'drawn over its measured curve');
    }
    // Measured curves (their whiskers drawn apart), fitted curves with the two bounds of their bands,
    // and the small-strain rings, in uPlot's data.
    assert.equal(probability.seriesLabels.length,
      4 + 3 * fitted.length + (probability.curves.length - 4 - fitted.length));
    // The legend keeps fitted and measured apart: its key has a swatch of each, a fit's dashed over
    // a band; each group's entry stands for both of its series.
    const kinds = probability.legend.filter((entry) => entry.group === undefined && !entry.text.startsWith('outside'));
    assert.deepEqual(kinds.map((entry) => entry.text),
      ['measured, whiskers: 95 % interval', 'fit, band: 95 % interval']);
    assert.match(kinds[0].swatch, /\bmeasured\b.*\bwhiskers\b/);
    assert.match(kinds[1].swatch, /\bfitted\b.*\bband\b/);

    const critical = await chartContents(page, 'plot-critical');
    const expected = [];
    for (const fit of groupFits)
      for (const value of fit.critical)
        if (typeof value.estimate === 'number') expected.push([fit.group.primaries, value.estimate]);
    const fittedCritical = critical.curves.filter((curve) => curve.label.startsWith('fitted'));
    assert.deepEqual(fittedCritical.flatMap((curve) => curve.points).sort(), expected.sort());
    // v50 with its 95 % interval as a band: the summary's intervals.
    const v50 = groupFits.flatMap((fit) => fit.critical
      .filter((value) => value.level === 0.5 && typeof value.estimate === 'number')
      .map((value) => [fit.group.primaries, ...value.ci95]));
    const drawnV50 = fittedCritical.filter((curve) => curve.label.startsWith('fitted v50'))
      .flatMap((curve) => curve.points.map(([n], i) => [n, ...curve.band[i]]));
    assert.deepEqual(drawnV50.sort(), v50.sort());
    assert.equal(await page.locator('#correlations-table tbody tr').count(), 4);
    // A warning for each critical value the data do not pin down: an estimate outside its fit's
    // tested speeds, or an interval reaching more than 1.5 times beyond them; a mark in its cell.
    const far = groupFits.flatMap((fit) => fit.critical.filter((value) => {
      if (typeof value.estimate !== 'number') return false;
      const { min, max } = fit.validity.impact_speed;
      return value.estimate < min || value.estimate > max || value.ci95[0] < min / 1.5 || value.ci95[1] > max * 1.5;
    }));
    assert.ok(far.length > 0, 'three speeds, three replicates: some critical value is not pinned down');
    assert.equal(await page.locator('#correlations-warnings li').count(), far.length);
    assert.equal(await page.locator('#correlations-table .warning-mark').count(), far.length);
    // The scaling of v50 names N by the symbol the service gives the axis, its groups by their labels.
    assert.match(await page.locator('#correlations-scaling').textContent(),
      /Scaling of v50 at γ\/k_n = 0\.001 \(\w+\): v50 ∝ N\^-?[\d.]+(e-?\d+)? \[/);
    assert.deepEqual(page.foreignRequests, []);
    assert.deepEqual(page.problems, []);
  });
});

test('a table downloads', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'study-table-download', async () => {
    await openStudy(page);
    await page.locator('#tables-panel a[data-format="csv"]').waitFor();
    const link = page.locator('#tables-panel a[data-format="csv"]');
    const [download] = await Promise.all([page.waitForEvent('download'), link.click()]);
    const text = readFileSync(await download.path(), 'utf8');
    const direct = await fetch(`${service.origin}${await link.getAttribute('href')}`);
    assert.equal(text, await direct.text(), 'the file is what the service serves');
    const lines = text.trim().split('\r\n');
    const headerLines = Number(lines[0].split(',')[1]);
    const names = lines[headerLines].split(',');
    const rows = lines.slice(headerLines + 2).map((line) => line.split(','));
    assert.equal(rows.length, grid.grid_points.length, 'one row per grid point');
    const speed = names.indexOf('impact_speed');
    assert.ok(speed >= 0 && names.includes('p_stick'));
    assert.deepEqual([...new Set(rows.map((row) => Number(row[speed])))].sort((a, b) => a - b), kSpeeds);
    assert.deepEqual(page.foreignRequests, []);
  });
});

// A definition list's entries, by label.
function facts(page, selector) {
  return page.locator(selector).evaluate((list) => Object.fromEntries([...list.querySelectorAll('dt')]
    .map((term) => [term.textContent, term.nextElementSibling.textContent])));
}
