// Units on the page in real Chromium: every speed, energy, time and length label of the study page
// and the case page carries the study's units as the API gives them, SI (m/s, J, s, m, kg) for a
// physical study and d/τ, k_n d², τ, d for a reduced one, and the numbers shown are the result's in
// those units. The physical study is watched while it runs: its state, its progress bar, and its
// correlations appearing once it ends, without a reload.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { openPage, serviceAndBrowser, smallStudy, until, withScreenshot } from './support.mjs';

let service;
let browser;

// The default study (studies/default.study.json) made small: 2 speeds x 2 N, adhesive wall, one
// replicate, so that its cases take seconds.
function smallPhysicalStudy() {
  const study = JSON.parse(readFileSync(new URL('../../studies/default.study.json', import.meta.url), 'utf8'));
  delete study.$schema;
  study.name = 'physical units';
  study.description = 'A small physical study';
  study.axes = { impact_speed: { values: [8, 40] }, primaries: { values: [8, 16] } };
  study.replicates = { count: 1, seed: 3 };
  return study;
}

serviceAndBrowser((started) => ({ service, browser } = started));

// Texts of the page's labels: headers, fact labels, chart axis labels and legend entries.
function labels(page) {
  return page.evaluate(() => ({
    headers: [...document.querySelectorAll('th')].map((node) => node.textContent),
    facts: Object.fromEntries([...document.querySelectorAll('dl.facts dt')].map((node) => [node.textContent,
      node.nextElementSibling.textContent])),
    options: [...document.querySelectorAll('option')].map((node) => node.textContent),
    axes: Object.fromEntries([...document.querySelectorAll('.chart')].filter((chart) => chart.uplot)
      .map((chart) => [chart.id, chart.uplot.axes.map((axis) => axis.label)])),
  }));
}

const formatted = (value) => String(Number(value.toPrecision(4)));

async function checkCasePage(page, caseId, { speed, energy, time, length }) {
  await page.goto(`${service.origin}/?case=${caseId}`);
  await page.locator('#fragments-table').waitFor();
  const detail = await service.get(`/api/cases/${caseId}`);
  const shown = await labels(page);
  const result = detail.result;
  const scale = result.units.physical || { speed_m_per_s: 1, energy_J: 1, time_s: 1 };
  assert.equal(Number(shown.facts[`impact speed (${speed})`]),
    Number(formatted(result.dimensionless.impact_speed * scale.speed_m_per_s)));
  const energyFacts = await page.locator(`dt:text-is("impact kinetic energy (${energy})")`).count();
  assert.equal(energyFacts, 2, 'both impact kinetic energies are labelled with the unit');
  assert.equal(Number(shown.facts[`impact kinetic energy (${energy})`]),
    Number(formatted(result.energy.impact_kinetic * scale.energy_J)));
  assert.equal(Number(shown.facts[`threshold quiet window (${time})`]),
    Number(formatted(result.outcome.thresholds.quiet_window * scale.time_s)));
  for (const header of [`Normal velocity (${speed})`, `Rg (${length})`,
    `Initial (${energy})`]) assert.ok(shown.headers.includes(header), header);
  return { shown, result };
}

test('a physical study: SI on the study page, running and done, on the case page; its fits once it ends', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'units-physical', async () => {
    const id = await service.submit(smallPhysicalStudy());
    const study = await service.get(`/api/studies/${id}`);
    assert.deepEqual(study.units, { system: 'physical', length: 'm', mass: 'kg', time: 's', speed: 'm/s',
      energy: 'J' });
    await page.goto(`${service.origin}/?study=${id}`);
    await page.locator('#study-state').waitFor();
    assert.match(await page.locator('#study-state').textContent(), /^(queued|running)$/);
    assert.equal(await page.locator('.progress-line [role="progressbar"]').count(), 1);
    // The page follows the study to its end without a reload, and then shows its fits.
    await page.waitForFunction(() => document.getElementById('study-state').textContent === 'complete', null,
      { timeout: 120000 });
    // The fits shown are those of all 4 cases (the refresh when the study ended), not of the cases
    // done when results first arrived.
    await page.waitForFunction(() => {
      const table = document.getElementById('correlations-table');
      if (!table) return false;
      const column = [...table.querySelectorAll('th')].findIndex((th) => th.textContent === 'cases');
      return [...table.querySelectorAll('tbody tr')].reduce((sum, row) => sum + Number(row.cells[column].textContent),
        0) === 4;
    }, null, { timeout: 60000 });
    assert.equal(await page.locator('#panel-correlations').isVisible(), true);
    assert.equal(Number(await page.locator('.progress-line [role="progressbar"]').getAttribute('aria-valuenow')), 4);
    await page.waitForFunction(() => document.getElementById('plot-critical').uplot);

    const shown = await labels(page);
    assert.ok(shown.headers.includes('impact speed v₀ (m/s)'), 'axes and case tables');
    assert.ok(shown.options.includes('impact speed v₀ (m/s)'), 'the x-axis choice');
    assert.equal(shown.axes['plot-probability'][0], 'impact speed v₀ (m/s)');
    assert.equal(shown.axes['plot-retained'][0], 'impact speed v₀ (m/s)');
    assert.equal(shown.axes['plot-critical'][1], 'critical speed (m/s)');
    assert.ok(shown.headers.includes('v50 (m/s), 95 %'), 'the correlations table');
    assert.doesNotMatch(JSON.stringify(shown), /d\/τ|k_n d²/);

    const cases = await service.get(`/api/studies/${id}/case-table?limit=4`);
    const { shown: caseLabels, result } = await checkCasePage(page, cases.items.at(-1).id, { speed: 'm/s', energy: 'J',
      time: 's', length: 'm' });
    assert.equal(Number(caseLabels.facts['impact speed (m/s)']), Number(formatted(result.si.impact_speed_m_per_s)));
    assert.equal(Number(caseLabels.facts['impact speed (d/τ)']), Number(formatted(result.dimensionless.impact_speed)),
      'the reduced speed, labelled');
    assert.equal(Number(caseLabels.facts['impact kinetic energy (J)']),
      Number(formatted(result.si.impact_kinetic_energy_J)));
    assert.equal(Number(caseLabels.facts['threshold quiet window (s)']), Number(formatted(result.si.quiet_window_s)));
    assert.match(caseLabels.facts['grid point'], /impact speed v₀ \(m\/s\) = 40/);
    assert.deepEqual(page.problems, []);
  });
});

test('a reduced study: d/τ, k_n d², τ and d', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'units-reduced', async () => {
    const id = await service.submit(smallStudy('reduced units', { speeds: [0.005, 0.3], gammas: [0.001],
      replicates: 1 }));
    await service.waitComplete(id);
    const study = await service.get(`/api/studies/${id}`);
    assert.deepEqual(study.units, { system: 'reduced', length: 'd', mass: 'm', time: 'tau', speed: 'd/tau',
      energy: 'k_n d^2' });
    await page.goto(`${service.origin}/?study=${id}`);
    await page.waitForFunction(() => document.getElementById('plot-critical')?.uplot &&
      document.querySelector('#case-table table'));
    assert.equal(await page.locator('#study-state').textContent(), 'complete');
    const shown = await labels(page);
    assert.ok(shown.headers.includes('impact speed v₀ (d/τ)'));
    assert.equal(shown.axes['plot-probability'][0], 'impact speed v₀ (d/τ)');
    assert.equal(shown.axes['plot-critical'][1], 'critical speed (d/τ)');
    assert.doesNotMatch(JSON.stringify(shown), /m\/s|\(J\)/);

    const cases = await service.get(`/api/studies/${id}/case-table?limit=4`);
    const { shown: caseLabels } = await checkCasePage(page, cases.items.at(-1).id, { speed: 'd/τ', energy: 'k_n d²',
      time: 'τ', length: 'd' });
    assert.doesNotMatch(JSON.stringify(caseLabels), /m\/s|\(J\)|\(s\)|\(kg\)/);
    assert.deepEqual(page.problems, []);
  });
});

test('the studies list calls a finished study complete, not active', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'units-list', async () => {
    await until(async () => (await service.get('/api/progress')).items.every((study) => study.progress.complete),
      { timeoutMs: 120000, what: 'every study to end' });
    await page.goto(service.origin);
    await page.locator('#studies-table').waitFor();
    const states = await page.locator('#studies-table .study-state').allTextContents();
    assert.deepEqual(states, ['complete', 'complete']);
    assert.doesNotMatch(await page.locator('#studies-table').textContent(), /active/);
  });
});
