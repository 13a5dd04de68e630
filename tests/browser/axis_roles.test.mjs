// The study page gives an axis its role by the case field it sets, not by the name the study used
// (a study may write the alias impact_speed or the pointer /impact/speed, docs/ORCHESTRATOR.md),
// in real Chromium: two studies alike but for how they name their axes, one by alias
// (impact_speed, primaries) and one by pointer (/impact/speed, /cluster/generator/primaries), both
// sweeping /wall/adhesive, show the same page: x along the impact speed (the energy per contact
// offered along it), one curve per N, the critical speed against N with its measured points and
// fitted curves, fitted curves over the probabilities, the correlations table. An address that
// names the pointer study's axes by alias (x=primaries, s.impact_speed, f.axis.primaries) still
// chooses them, and is rewritten to the study's names.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openPage, serviceAndBrowser, smallStudy, withScreenshot } from './support.mjs';

let service;
let browser;

serviceAndBrowser((started) => ({ service, browser } = started));

const kSpeeds = [0.005, 0.03, 0.3];

// 3 speeds x N 8, 16 x both walls x 2 replicates = 24 cases, the axes named by `speed` and `size`.
function wallStudy(name, speed, size) {
  const study = smallStudy(name, { speeds: kSpeeds, replicates: 2 });
  study.base.material = { gamma_over_kn: 0.001 };
  study.axes = { [speed]: { values: kSpeeds }, [size]: { values: [8, 16] },
    '/wall/adhesive': { values: [true, false] } };
  return study;
}

// What the page shows of each axis's role, once the fits are drawn.
async function roles(page, origin, id, search = '') {
  await page.goto(`${origin}/?study=${id}${search}`);
  await page.waitForFunction(() => document.getElementById('plot-probability')?.uplot, null, { timeout: 30000 });
  const x = await page.locator('#choose-x').inputValue();
  await page.waitForFunction(() => Number(document.getElementById('plot-critical').dataset.fitted) > 0 &&
    Number(document.getElementById('plot-probability').dataset.fitted) > 0 &&
    document.querySelector('#correlations-table'), null, { timeout: 60000 }).catch(() => {});
  return page.evaluate((chosenX) => {
    const chart = (id) => document.getElementById(id);
    const measured = (id) => (chart(id).curves || []).filter((curve) => curve.style === 'measured');
    const critical = chart('plot-critical');
    return {
      x: chosenX,
      xLabel: chart('plot-probability').uplot.axes[0].label,
      xChoices: [...document.querySelectorAll('#choose-x option')].map((node) => node.textContent),
      slices: [...document.querySelectorAll('#plot-controls select[data-slice]')].map((node) => node.dataset.slice),
      curves: measured('plot-probability').map((curve) => curve.label).sort(),
      retainedCurves: measured('plot-retained').map((curve) => curve.label).sort(),
      probabilityFitted: Number(chart('plot-probability').dataset.fitted) > 0,
      critical: {
        hidden: document.getElementById('panel-critical').hidden,
        heading: document.querySelector('#panel-critical h2').textContent,
        xLabel: critical.uplot?.axes[0].label,
        yLabel: critical.uplot?.axes[1].label,
        measuredPoints: (critical.curves || []).filter((curve) => curve.style === 'points')
          .flatMap((curve) => curve.points).length > 0,
        fitted: Number(critical.dataset.fitted) > 0,
      },
      correlationsColumns: [...document.querySelectorAll('#correlations-table th')].map((node) => node.textContent),
      fragmentSeries: (chart('plot-fragments').curves || []).length,
    };
  }, x);
}

test('a study naming its axes by pointer: the same roles as by alias', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'axis-roles', async () => {
    const byAlias = await service.submit(wallStudy('by alias', 'impact_speed', 'primaries'));
    const byPointer = await service.submit(wallStudy('by pointer', '/impact/speed', '/cluster/generator/primaries'));
    await service.waitComplete(byAlias);
    await service.waitComplete(byPointer);

    const aliasRoles = await roles(page, service.origin, byAlias);
    assert.equal(aliasRoles.x, 'impact_speed');
    assert.deepEqual(aliasRoles.xChoices, ['impact speed v₀ (d/τ)', 'primaries N',
      'energy per contact E_kin / (N_c E_break)']);
    assert.deepEqual(aliasRoles.curves, ['N = 8', 'N = 16'].sort());
    assert.deepEqual(aliasRoles.slices, ['/wall/adhesive']);
    assert.equal(aliasRoles.critical.hidden, false);
    assert.ok(aliasRoles.critical.measuredPoints && aliasRoles.critical.fitted && aliasRoles.probabilityFitted,
      JSON.stringify(aliasRoles));

    const pointerRoles = await roles(page, service.origin, byPointer);
    assert.equal(pointerRoles.x, '/impact/speed', 'x along the impact speed by default');
    assert.deepEqual({ ...pointerRoles, x: aliasRoles.x }, aliasRoles);
    assert.deepEqual(page.problems, []);
  });
});

test("an address naming a pointer study's axes by alias chooses them", async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'axis-roles-address', async () => {
    const id = await service.submit(wallStudy('by pointer, by address', '/impact/speed',
      '/cluster/generator/primaries'));
    await service.waitComplete(id);
    const cases = await service.get(`/api/studies/${id}/case-table?axis.%2Fcluster%2Fgenerator%2Fprimaries=16`);
    assert.equal(cases.total, 12);

    await page.goto(`${service.origin}/?study=${id}&x=primaries&s.impact_speed=0.03&f.axis.primaries=16`);
    await page.waitForFunction(() => document.getElementById('plot-probability')?.uplot &&
      document.querySelector('#case-table table'));
    assert.equal(await page.locator('#choose-x').inputValue(), '/cluster/generator/primaries');
    assert.equal(await page.locator('select[data-slice="/impact/speed"]').inputValue(), '0.03');
    assert.equal(await page.locator('#case-table').getAttribute('data-total'), '12');
    assert.equal(await page.locator('select[data-filter-axis="/cluster/generator/primaries"]').inputValue(), '16');
    const search = new URLSearchParams(new URL(page.url()).search);
    assert.deepEqual(['x', 's./impact/speed', 'f.axis./cluster/generator/primaries'].map((name) => search.get(name)),
      ['/cluster/generator/primaries', '0.03', '16']);
    assert.deepEqual(page.problems, []);
  });
});
