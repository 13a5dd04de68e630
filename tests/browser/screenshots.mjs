// Not a test: writes the screenshots of docs/WEB.md (docs/figures/web-*.png) of the default study
// (studies/default.study.json), at 1280 px and the study page also at 1920 px, and of a study with
// an adaptive search, the size ladder at N = 128 (studies/size_ladder_n128.study.json), at 1280 and
// 1920 px. Usage, from the repository root after scripts/setup.sh, either of
//   AEROBREAK_BINARY=build/aerobreak node tests/browser/screenshots.mjs [search]
//       (runs the studies first: 320 cases, about 5 min on 2 cores, and 210 cases, about 4 min)
//   AEROBREAK_BINARY=build/aerobreak AEROBREAK_STORE=runs/default.sqlite \
//     AEROBREAK_SEARCH_STORE=runs/size_ladder_n128.sqlite node tests/browser/screenshots.mjs [search]
//       (the stores README's first command and docs/STUDIES.md's ladder leave)
// With `search`, only the search study's pictures.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { Service, launchBrowser, openPage } from './support.mjs';

const figures = path.resolve('docs/figures');
const onlySearch = process.argv[2] === 'search';
const browser = await launchBrowser();

// A service of `store` (or a fresh one) and the id of its study `name`, run from `file` when no
// store is given.
async function serveStudy(store, name, file) {
  const service = await Service.start([], { store: store && path.resolve(store) });
  if (store) return { service, id: (await service.get('/api/studies')).items.find((study) => study.name === name).id };
  const { $schema, ...study } = JSON.parse(readFileSync(file, 'utf8'));
  const id = await service.submit(study);
  await service.waitComplete(id, 3600000);
  return { service, id };
}

// `shoot(search, name, ready, options)`: the page at `search`, once `ready()`, as web-NAME.png.
function shooter(page, service) {
  return async (search, name, ready, { width = 1280, height = 900, fullPage = false } = {}) => {
    await page.setViewportSize({ width, height });
    await page.goto(`${service.origin}/${search}`);
    await ready();
    await page.screenshot({ path: path.join(figures, `web-${name}.png`), fullPage });
  };
}

const fittedOn = (page) => () => page.waitForFunction(() =>
  Number(document.getElementById('plot-probability')?.dataset.fitted) > 0 &&
  document.getElementById('plot-fragments')?.uplot);

// The default study's page, the studies list, a case and the submit form.
async function defaultStudyPictures(service, id) {
  const page = await openPage(browser, service);
  const shoot = shooter(page, service);
  const fitted = fittedOn(page);
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
}

// The search study's page at 1280 (whole) and 1920 px, on the adhesive wall.
async function searchStudyPictures(service, id) {
  const page = await openPage(browser, service);
  const shoot = shooter(page, service);
  const ready = async () => {
    await fittedOn(page)();
    await page.locator('#search-estimates').waitFor();
  };
  await shoot(`?study=${id}&s.%2Fwall%2Fadhesive=true`, 'study-search', ready, { fullPage: true });
  await shoot(`?study=${id}&s.%2Fwall%2Fadhesive=true`, 'study-search-1920', ready, { width: 1920, height: 1600 });
}

// Serves `name` (from `store` or run from `file`) and takes `pictures(service, id)` of it.
async function picturesOf(store, name, file, pictures) {
  const { service, id } = await serveStudy(store, name, file);
  try {
    await pictures(service, id);
  } finally {
    await service.stop();
  }
}

try {
  if (!onlySearch)
    await picturesOf(process.env.AEROBREAK_STORE, 'default', 'studies/default.study.json', defaultStudyPictures);
  await picturesOf(process.env.AEROBREAK_SEARCH_STORE, 'size ladder N=128', 'studies/size_ladder_n128.study.json',
    searchStudyPictures);
} finally {
  await browser.close();
}
