// Not a test: writes the screenshots of docs/WEB.md (docs/figures/web-*.png) of the default study
// (studies/default.study.json), at 1280 px and the study page also at 1920 px. Usage, from the
// repository root after scripts/setup.sh, either of
//   AEROBREAK_BINARY=build/aerobreak node tests/browser/screenshots.mjs
//       (runs the default study first: 320 cases, about 5 min on 2 cores)
//   AEROBREAK_BINARY=build/aerobreak AEROBREAK_STORE=runs/default.sqlite node tests/browser/screenshots.mjs
//       (the store README's first command leaves)
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { Service, launchBrowser, openPage } from './support.mjs';

const figures = path.resolve('docs/figures');
const store = process.env.AEROBREAK_STORE;
const service = await Service.start([], { store: store && path.resolve(store) });
const browser = await launchBrowser();

async function defaultStudy() {
  if (store) return (await service.get('/api/studies')).items.find((study) => study.name === 'default').id;
  const { $schema, ...study } = JSON.parse(readFileSync('studies/default.study.json', 'utf8'));
  const id = await service.submit(study);
  await service.waitComplete(id, 3600000);
  return id;
}

try {
  const id = await defaultStudy();
  const page = await openPage(browser, service);
  const shoot = async (search, name, ready, { width = 1280, height = 900, fullPage = false } = {}) => {
    await page.setViewportSize({ width, height });
    await page.goto(`${service.origin}/${search}`);
    await ready();
    await page.screenshot({ path: path.join(figures, `web-${name}.png`), fullPage });
  };
  const fitted = () => page.waitForFunction(() =>
    Number(document.getElementById('plot-probability')?.dataset.fitted) > 0 &&
    document.getElementById('plot-fragments')?.uplot);
  await shoot('', 'studies', () => page.locator('#studies-table').waitFor(), { height: 400 });
  await shoot(`?study=${id}&s.%2Fwall%2Fadhesive=true`, 'study', fitted);
  await page.evaluate(() => document.getElementById('plot-controls').scrollIntoView());
  await page.screenshot({ path: path.join(figures, 'web-study-plots.png') });
  await page.locator('#panel-correlations').screenshot({ path: path.join(figures, 'web-study-correlations.png') });
  await shoot(`?study=${id}&s.%2Fwall%2Fadhesive=true`, 'study-1920', fitted, { width: 1920, height: 1600 });
  const cases = await service.get(`/api/studies/${id}/case-table?outcome=break-up&axis.impact_speed=30&limit=1`);
  await shoot(`?case=${cases.items[0].id}`, 'case', () => page.locator('#fragments-table').waitFor(),
    { fullPage: true });
  await shoot('?submit', 'submit', async () => {
    await page.locator('#form-youngs_modulus').waitFor();
    await page.fill('#form-diameter', '20');
    await page.fill('#form-poisson_ratio', '0.7');
  });
} finally {
  await browser.close();
  await service.stop();
}
