// The studies list in real Chromium against a real `aerobreak serve`: a submitted study appears,
// its progress advances without a reload while it runs, and a study whose name and description
// are HTML is shown as text (inert).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openPage, serviceAndBrowser, smallStudy, until, withScreenshot } from './support.mjs';

let service;
let browser;

serviceAndBrowser((started) => ({ service, browser } = started));

test('the list shows a submitted study and its progress advances without a reload', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'studies-list-progress', async () => {
    await page.goto(`${service.origin}/`);
    await page.getByText('No studies yet').waitFor();
    await page.evaluate(() => { window.notReloaded = true; });
    // 24 cases of 128 primaries: several seconds on two ranks, so that the list polls meanwhile.
    const id = await service.submit(smallStudy('progress watch',
      { speeds: [0.01, 0.05, 0.2], primaries: [128], gammas: [0.001], replicates: 8 }));
    const row = page.locator('#studies-table tbody tr', { has: page.locator(`a[href="/?study=${id}"]`) });
    await row.waitFor({ timeout: 10000 });
    assert.equal(await row.locator('a.study-name').textContent(), 'progress watch');

    const seen = new Set();
    await until(async () => {
      const counts = await row.locator('.counts').textContent();
      seen.add((counts.match(/(\d+) done/) || [0, '0'])[1]);
      return counts.includes('24 done');
    }, { timeoutMs: 120000, intervalMs: 200, what: 'all 24 cases done on the page' });
    assert.ok(seen.size >= 2, `the done count changed on the page (seen ${[...seen].join(', ')})`);
    assert.ok(Number(await row.locator('.rate').textContent()) > 0, 'a rate in cases per hour');
    assert.match(await row.textContent(), /complete/);
    assert.equal(await page.evaluate(() => window.notReloaded), true, 'the page was not reloaded');
    assert.deepEqual(page.foreignRequests, []);
    assert.deepEqual(page.problems, []);
  });
});

test('a study named with HTML is shown as text, on the list and on its page', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'studies-list-xss', async () => {
    const name = '<img src=x onerror="window.injected=1">';
    const description = '<script>window.injected=2</script><b>bold?</b>';
    const study = smallStudy(name, { speeds: [0.01], primaries: [8], gammas: [0.001], replicates: 1, description });
    const id = await service.submit(study);
    await page.goto(`${service.origin}/`);
    const link = page.locator(`a[href="/?study=${id}"]`);
    await link.waitFor();
    assert.equal(await link.textContent(), name);
    await link.click();
    await page.locator('#study-name').waitFor();
    assert.equal(await page.locator('#study-name').textContent(), name);
    assert.equal(await page.locator('#study-description').textContent(), description);
    assert.equal(await page.locator('#view img, #view script, #view b').count(), 0, 'no element made from the texts');
    assert.equal(await page.evaluate(() => window.injected), undefined);
    assert.match(page.url(), new RegExp(`/\\?study=${id}$`));
    assert.deepEqual(page.foreignRequests, []);
    assert.deepEqual(page.problems, []);
  });
});

test('the page is served with a policy against inline scripts and other origins, and no request leaves loopback',
  async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'studies-list-policy', async () => {
    const response = await page.goto(`${service.origin}/`);
    const policy = response.headers()['content-security-policy'];
    assert.match(policy, /script-src 'self'(;|$)/);
    assert.match(policy, /default-src 'none'/);
    assert.doesNotMatch(policy, /unsafe-inline|unsafe-eval|\*/);
    // A request to another origin from inside the page is refused by the policy (and would be
    // aborted by the test's interception if it were not).
    const blocked = await page.evaluate(() => fetch('http://127.0.0.2:9/').then(() => 'sent', () => 'refused'));
    assert.equal(blocked, 'refused');
    const inlineRan = await page.evaluate(() => {
      const script = document.createElement('script');
      script.textContent = 'window.inline = 1';
      document.body.append(script);
      return window.inline;
    });
    assert.equal(inlineRan, undefined);
    // Node_modules files other than those the page names are not served.
    assert.equal((await service.request('GET', '/node_modules/uplot/package.json')).status, 404);
    assert.equal((await service.request('GET', '/package.json')).status, 404);
    assert.equal((await service.request('GET', '/vendor.json')).status, 404);
  });
});
