// The study page names its axes as the service describes them (GET /api/studies/ID: axes), in real
// Chromium: a reduced study sweeping the impact angle, a field the page has no name of its own
// for, shows the service's label and unit ("impact angle (deg)") in the axes table, the x and
// slice choosers, the plots and the case table, plots it in linear scale where the speed is in log
// scale, names the fragment series by the speed's symbol and unit ("v₀ = 0.3 d/τ"), and the case
// page names the grid point's axes the same way. A search study's axes table gives its searched
// axis's range, not every value the search ran.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openPage, serviceAndBrowser, smallStudy, withScreenshot } from './support.mjs';

let service;
let browser;

serviceAndBrowser((started) => ({ service, browser } = started));

function angleStudy() {
  const study = smallStudy('angles', { speeds: [0.005, 0.3], replicates: 1 });
  study.base.cluster.generator.primaries = 8;
  study.base.material = { gamma_over_kn: 0.001 };
  study.axes = { impact_speed: { values: [0.005, 0.3] }, '/impact/angle': { values: [0, 30] } };
  return study;
}

// Texts of the page's axis names: table headers, axes table rows, choosers, chart axes, curves.
function shownNames(page) {
  return page.evaluate(() => ({
    headers: [...document.querySelectorAll('#case-table th')].map((node) => node.textContent),
    axesTable: [...document.querySelectorAll('#axes-table tbody tr td:first-child')].map((node) => node.textContent),
    xChoices: [...document.querySelectorAll('#choose-x option')].map((node) => node.textContent),
    sliceLabels: [...document.querySelectorAll('#plot-controls label')].map((node) => node.firstChild.textContent),
    probability: {
      x: document.getElementById('plot-probability').uplot.axes[0].label,
      distr: document.getElementById('plot-probability').uplot.scales.x.distr,
    },
    fragments: (document.getElementById('plot-fragments').curves || []).map((curve) => curve.label),
  }));
}

test('an axis the page has no table of: label, unit and scale from the service', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'axes-angle', async () => {
    const id = await service.submit(angleStudy());
    await service.waitComplete(id);
    const described = (await service.get(`/api/studies/${id}`)).axes;
    assert.deepEqual(described.map(({ label, unit, log_scale: log }) => [label, unit, log]),
      [['impact speed v₀', 'd/tau', true], ['impact angle', 'deg', false]]);

    await page.goto(`${service.origin}/?study=${id}`);
    await page.waitForFunction(() => document.getElementById('plot-probability')?.uplot &&
      document.getElementById('plot-fragments')?.curves && document.querySelector('#case-table table'));
    const alongSpeed = await shownNames(page);
    assert.deepEqual(alongSpeed.axesTable, ['impact speed v₀ (d/τ)', 'impact angle (deg)']);
    assert.deepEqual(alongSpeed.xChoices, ['impact speed v₀ (d/τ)', 'impact angle (deg)',
      'energy per contact E_kin / (N_c E_break)']);
    assert.ok(alongSpeed.sliceLabels.includes('impact angle (deg) '), JSON.stringify(alongSpeed.sliceLabels));
    assert.ok(alongSpeed.headers.includes('impact angle (deg)'), JSON.stringify(alongSpeed.headers));
    assert.deepEqual(alongSpeed.probability, { x: 'impact speed v₀ (d/τ)', distr: 3 }, 'speed in log scale');
    assert.ok(alongSpeed.fragments.length > 0);
    for (const label of alongSpeed.fragments) assert.match(label, /^v₀ = (0\.005|0\.3) d\/τ \(\d+ results?\)$/);

    await page.selectOption('#choose-x', '/impact/angle');
    await page.waitForFunction(() => document.getElementById('plot-probability').uplot?.axes[0].label !==
      'impact speed v₀ (d/τ)');
    const alongAngle = await shownNames(page);
    assert.deepEqual(alongAngle.probability, { x: 'impact angle (deg)', distr: 1 }, 'the angle in linear scale');
    assert.ok(alongAngle.sliceLabels.includes('impact speed v₀ (d/τ) '), JSON.stringify(alongAngle.sliceLabels));

    const cases = await service.get(`/api/studies/${id}/case-table?limit=4`);
    await page.goto(`${service.origin}/?case=${cases.items.at(-1).id}`);
    await page.locator('#case-title').waitFor();
    const gridPoint = await page.locator('dt:text-is("grid point") + dd').textContent();
    assert.match(gridPoint, /^impact speed v₀ \(d\/τ\) = [\d.]+, impact angle \(deg\) = (0|30)$/);
    assert.deepEqual(page.problems, []);
  });
});

test("a search study's axes table: the searched axis by its range and the values run", async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'axes-search', async () => {
    const study = smallStudy('search', { speeds: [0.01], primaries: [8, 16], gammas: [0.001], replicates: 1 });
    delete study.axes.impact_speed;
    study.search = { axis: 'impact_speed', range: { from: 0.005, to: 0.3 }, relative_width: 0.5, budget: 20,
      batch: 10, initial: 10 };
    const id = await service.submit(study);
    await service.waitComplete(id);
    const run = (await service.get(`/api/studies/${id}/grid`)).axes.find((axis) => axis.name === 'impact_speed');
    assert.ok(run.values.length > 2);
    await page.goto(`${service.origin}/?study=${id}`);
    await page.waitForFunction(() => document.getElementById('plot-probability')?.uplot);
    const rows = await page.locator('#axes-table tbody tr').evaluateAll((trs) => trs.map((tr) =>
      [...tr.cells].map((cell) => cell.textContent)));
    assert.deepEqual(rows, [['γ/k_n', '0.001'], ['primaries N', '8, 16'],
      ['impact speed v₀ (d/τ)', `searched over 0.005–0.3: ${run.values.length} values run`]]);
    assert.deepEqual(page.problems, []);
  });
});
