// Submitting and cancelling from the page in real Chromium: a bad study shows each validation
// error at the field its JSON pointer names; a study read from a file is submitted as JSON; a
// running study is cancelled; with a token configured the page asks for it and sends it as a
// bearer token.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import { Service, launchBrowser, openPage, smallStudy, until, withScreenshot } from './support.mjs';

const kToken = 'a-test-token-0123456789';
let service;
let guarded;
let browser;

before(async () => {
  service = await Service.start();
  const tokenFile = path.join(service.directory, 'token');
  writeFileSync(tokenFile, `${kToken}\n`);
  guarded = await Service.start(['--token-file', tokenFile]);
  browser = await launchBrowser();
});

after(async () => {
  await browser?.close();
  await service?.stop();
  await guarded?.stop();
});

test('a bad study shows its errors at the fields their pointers name', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'submit-errors', async () => {
    await page.goto(`${service.origin}/?submit`);
    const study = smallStudy('bad', { speeds: [], replicates: 0 });
    study.execution.max_attempts = 0;
    await page.fill('#study-json', JSON.stringify(study, null, 2));
    await page.click('#submit-study');
    await page.locator('#violations li').first().waitFor();
    const pointers = await page.locator('#violations li').evaluateAll((items) => items.map((item) => item.dataset.pointer));
    const expected = ['/axes/impact_speed/values', '/replicates/count', '/execution/max_attempts'];
    assert.deepEqual(pointers.sort(), [...expected].sort());
    for (const pointer of expected) {
      const field = page.locator(`#document-tree .field.invalid[data-pointer="${pointer}"]`);
      assert.equal(await field.count(), 1, pointer);
      assert.match(await field.locator(':scope > .message').first().textContent(), /must/, pointer);
    }
    assert.equal(await page.locator('#document-tree .field.invalid').count(), expected.length);
    assert.equal((await service.get('/api/studies')).total, 0, 'nothing stored');

    await page.fill('#study-json', '{"name": ');
    await page.click('#submit-study');
    await page.waitForFunction(() => /not JSON/.test(document.getElementById('submit-error')?.textContent || ''));
    assert.deepEqual(page.foreignRequests, []);
  });
});

test('a study read from a file is submitted as application/json, and a running study is cancelled', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'submit-cancel', async () => {
    const posts = [];
    page.on('request', (request) => { if (request.method() === 'POST') posts.push(request); });
    await page.goto(`${service.origin}/?submit`);
    // 120 cases of 128 primaries: about 20 s of work on two ranks, so that there is time to cancel.
    const study = smallStudy('to cancel', { speeds: [0.01, 0.05, 0.1, 0.2, 0.3], primaries: [128], gammas: [0.001, 0.01], replicates: 12 });
    const file = path.join(service.directory, 'study.json');
    writeFileSync(file, JSON.stringify(study));
    await page.setInputFiles('#study-file', file);
    await page.waitForFunction(() => document.getElementById('study-json').value.includes('to cancel'));
    await page.click('#submit-study');
    const link = page.locator('#submit-receipt a');
    await link.waitFor();
    assert.equal(posts[0].headers()['content-type'], 'application/json');
    await link.click();
    await page.locator('#cancel-study').click();
    await page.waitForFunction(() => /cancelled/.test(document.getElementById('progress').textContent));
    const id = Number(new URL(page.url()).searchParams.get('study'));
    const progress = await service.get(`/api/studies/${id}/progress`);
    assert.ok(progress.counts.cancelled > 0, JSON.stringify(progress));
    assert.equal((await service.get(`/api/studies/${id}`)).status, 'cancelled');
    await until(async () => (await service.get(`/api/studies/${id}/progress`)).complete, { what: 'running cases to end' });
    await page.waitForFunction(() => !document.getElementById('cancel-study'), null, { timeout: 15000 });
    assert.deepEqual(page.foreignRequests, []);
    assert.deepEqual(page.problems, []);
  });
});

test('with a token configured the page asks for it and sends it as a bearer token', async () => {
  const page = await openPage(browser, guarded);
  await withScreenshot(page, 'submit-token', async () => {
    const posts = [];
    page.on('request', (request) => { if (request.method() === 'POST') posts.push(request.headers()); });
    await page.goto(`${guarded.origin}/?submit`);
    await page.fill('#study-json', JSON.stringify(smallStudy('with token', { speeds: [0.01], primaries: [8], gammas: [0.001], replicates: 1 })));
    await page.click('#submit-study');
    await page.locator('#token-dialog[open]').waitFor();
    await page.fill('#token-input', kToken);
    await page.click('#token-ok');
    await page.locator('#submit-receipt a').waitFor();
    assert.equal(posts.length, 2, 'one refused without the token, one with it');
    assert.equal(posts[0].authorization, undefined);
    assert.equal(posts[1].authorization, `Bearer ${kToken}`);
    assert.equal((await guarded.get('/api/studies')).total, 1);
    assert.deepEqual(page.foreignRequests, []);
    assert.deepEqual(page.problems, []);
  });
});
