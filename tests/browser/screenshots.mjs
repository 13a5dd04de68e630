// Not a test: writes the screenshots of docs/WEB.md (docs/figures/web-*.png) from a real service
// with a small study. Usage, from the repository root after scripts/setup.sh:
//   AEROBREAK_BINARY=build/aerobreak node tests/browser/screenshots.mjs
import path from 'node:path';
import { Service, launchBrowser, openPage, smallStudy } from './support.mjs';

const figures = path.resolve('docs/figures');
const service = await Service.start();
const browser = await launchBrowser();
try {
  const id = await service.submit(smallStudy('speed sweep, N = 8 and 16', {
    speeds: [0.005, 0.01, 0.02, 0.05, 0.1, 0.3], replicates: 4,
    description: 'Ballistic clusters hitting an adhesive wall head-on, two gamma/k_n' }));
  await service.waitComplete(id);
  const page = await openPage(browser, service);
  await page.setViewportSize({ width: 1100, height: 760 });
  const shoot = async (search, name, ready) => {
    await page.goto(`${service.origin}/${search}`);
    await ready();
    await page.screenshot({ path: path.join(figures, `web-${name}.png`) });
  };
  await shoot('', 'studies', () => page.locator('#studies-table').waitFor());
  await shoot(`?study=${id}`, 'study', () => page.waitForFunction(() => document.getElementById('plot-fragments')?.dataset.series));
  await page.locator('#panel-probability').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(figures, 'web-study-plots.png') });
  await shoot("?case=40", 'case', () => page.locator('#fragments-table').waitFor());
  await shoot('?submit', 'submit', async () => {
    const bad = smallStudy('bad', { speeds: [], replicates: 0 });
    await page.fill('#study-json', JSON.stringify(bad, null, 1));
    await page.click('#submit-study');
    await page.locator('#document-tree').waitFor();
    await page.locator('#violations').scrollIntoViewIfNeeded();
  });
} finally {
  await browser.close();
  await service.stop();
}
