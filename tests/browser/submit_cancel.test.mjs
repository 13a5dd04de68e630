// Submitting and cancelling from the page in real Chromium: the form for the common physical study
// starts from the default study, checks each field as the user types (with the schema's limits)
// and keeps the JSON view in step; a bad study shows each validation error at the field its JSON
// pointer names; a study read from a file is submitted as JSON; a running study is cancelled; with
// a token configured the page asks for it and sends it as a bearer token.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync } from 'node:fs';
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

const readJson = (relative) => JSON.parse(readFileSync(new URL(relative, import.meta.url), 'utf8'));

// The schema's constraints at a "file#/json/pointer" reference, resolved against schemas/.
function schemaAt(reference) {
  const [file, pointer] = reference.split('#');
  let node = readJson(`../../schemas/${file}`);
  for (const token of pointer.split('/').slice(1)) node = node[token.replaceAll('~1', '/').replaceAll('~0', '~')];
  assert.ok(node, reference);
  return node;
}

test("the form's limits are the schema's at each field", async () => {
  const { kFormFields } = await import('../../web/src/views/submit_fields.js');
  for (const field of kFormFields) {
    const schema = schemaAt(field.schema);
    for (const key of ['minimum', 'exclusiveMinimum', 'maximum', 'exclusiveMaximum', 'minLength', 'maxLength'])
      assert.equal(field[key], schema[key], `${field.id}: ${key}`);
    if (field.kind === 'choice') for (const [value] of field.options) assert.ok(schema.enum.includes(value),
      `${field.id}: ${value}`);
  }
});

const jsonView = async (page) => JSON.parse(await page.inputValue('#study-json'));
const message = (page, id) => page.textContent(`#form-${id}-message`);

test('the form: the default study offered, fields checked as typed, the JSON view in step, a study sent', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'submit-form', async () => {
    await page.goto(`${service.origin}/?submit`);
    await page.locator('#form-youngs_modulus').waitFor();
    const { $schema, ...fileStudy } = readJson('../../studies/default.study.json');
    assert.deepEqual(await jsonView(page), fileStudy, 'the default study, as in studies/default.study.json');
    assert.equal(await page.inputValue('#form-youngs_modulus'), '2.5e10');
    assert.equal(await page.inputValue('#form-speeds'), '4, 8, 12, 16, 20, 25, 30, 40');
    assert.equal(await page.textContent('[data-pointer="/axes/impact_speed/values"] .unit'), 'm/s');
    assert.match(await page.textContent('#form-summary'), /^320 cases/);

    // Out of the schema's range: the message at once, at the field; the document keeps its value.
    await page.fill('#form-poisson_ratio', '0.7');
    assert.match(await message(page, 'poisson_ratio'), /must be less than 0\.5/);
    assert.equal(await page.getAttribute('#form-poisson_ratio', 'aria-invalid'), 'true');
    assert.equal((await jsonView(page)).base.material.poisson_ratio, 0.3);
    assert.match(await page.textContent('#submit-note'), /1 field needs attention/);
    // Typed key by key: each keystroke checked, the valid value written.
    await page.fill('#form-poisson_ratio', '');
    assert.match(await message(page, 'poisson_ratio'), /needs a value/);
    await page.locator('#form-poisson_ratio').pressSequentially('0.25');
    assert.equal(await message(page, 'poisson_ratio'), '');
    assert.equal((await jsonView(page)).base.material.poisson_ratio, 0.25);
    // Allowed but unlikely: said, not refused; outside the schema's range (a diameter in nm typed as m): refused.
    await page.fill('#form-diameter', '1e-4');
    assert.match(await message(page, 'diameter'), /unusual/);
    assert.equal(await page.getAttribute('#form-diameter', 'aria-invalid'), 'false');
    await page.fill('#form-diameter', '20');
    assert.match(await message(page, 'diameter'), /must be at most 0.001/);
    assert.equal(await page.getAttribute('#form-diameter', 'aria-invalid'), 'true');
    await page.fill('#form-diameter', '2e-8');
    await page.fill('#form-speeds', '5, fast');
    assert.match(await message(page, 'speeds'), /“fast” is not a number/);
    await page.fill('#form-speeds', '10, 40');
    await page.fill('#form-primaries', '8.5');
    assert.match(await message(page, 'primaries'), /not a whole number/);
    await page.fill('#form-primaries', '8');
    await page.locator('[data-pointer="/axes/~1wall~1adhesive/values"] input').nth(1).uncheck();
    await page.locator('[data-pointer="/axes/~1wall~1adhesive/values"] input').nth(0).uncheck();
    assert.match(await page.textContent('#form-walls-message'), /at least one wall/);
    await page.locator('[data-pointer="/axes/~1wall~1adhesive/values"] input').nth(0).check();
    await page.fill('#form-replicates', '1');
    await page.selectOption('#form-generator', 'tunable');
    assert.equal(await page.locator('#form-fractal_dimension').isVisible(), true);
    assert.equal((await jsonView(page)).base.cluster.generator.fractal_dimension, 1.8);
    await page.fill('#form-fractal_dimension', '3.1');
    assert.match(await message(page, 'fractal_dimension'), /at most 2\.8/);
    await page.selectOption('#form-generator', 'ballistic');
    assert.equal(await page.locator('#form-fractal_dimension').isVisible(), false);
    assert.equal('fractal_dimension' in (await jsonView(page)).base.cluster.generator, false);

    // The reduced example: its one size, set in the base, shows as the sizes; its material is the
    // JSON view's; its speeds are in d/τ. Back to the study being edited through the JSON view.
    const edited = await jsonView(page);
    await page.selectOption('#choose-template', '1');
    assert.equal(await page.inputValue('#form-primaries'), '16');
    assert.equal(await message(page, 'primaries'), '');
    assert.equal(await page.isDisabled('#form-youngs_modulus'), true);
    assert.match(await page.textContent('#form-material-note'), /reduced units/);
    assert.equal(await page.textContent('[data-pointer="/axes/impact_speed/values"] .unit'), 'd/τ');

    // While the JSON view is not JSON the form waits, so that it cannot overwrite the text typed.
    await page.fill('#study-json', '{"name": ');
    assert.match(await page.textContent('#study-json-message'), /not JSON/);
    assert.equal(await page.isDisabled('#form-name'), true);

    // The JSON view: an edit there shows in the form.
    edited.name = 'from the form';
    await page.fill('#study-json', JSON.stringify(edited, null, 2));
    assert.equal(await page.inputValue('#form-name'), 'from the form');
    assert.match(await page.textContent('#form-summary'), /^2 cases/);
    assert.equal(await page.textContent('#submit-note'), '');

    await page.click('#submit-study');
    await page.locator('#submit-receipt a').waitFor();
    const href = await page.locator('#submit-receipt a').evaluate((a) => a.href);
    const id = Number(new URL(href).searchParams.get('study'));
    const stored = await service.get(`/api/studies/${id}`);
    assert.equal(stored.units.system, 'physical');
    assert.equal(stored.cases, 2);
    assert.deepEqual(stored.document.axes, { impact_speed: { values: [10, 40] }, '/wall/adhesive': { values: [true] },
      primaries: { values: [8] } });
    assert.equal(stored.document.base.material.poisson_ratio, 0.25);
    await service.request('POST', `/api/studies/${id}/cancel`, {});
    assert.deepEqual(page.foreignRequests, []);
    assert.deepEqual(page.problems, []);
  });
});

test('a bad study shows its errors at the fields their pointers name', async () => {
  const page = await openPage(browser, service);
  await withScreenshot(page, 'submit-errors', async () => {
    await page.goto(`${service.origin}/?submit`);
    const storedBefore = (await service.get('/api/studies')).total;
    const study = smallStudy('bad', { speeds: [], replicates: 0 });
    study.execution.max_attempts = 0;
    await page.fill('#study-json', JSON.stringify(study, null, 2));
    await page.click('#submit-study');
    await page.locator('#violations li').first().waitFor();
    const pointers = await page.locator('#violations li')
      .evaluateAll((items) => items.map((item) => item.dataset.pointer));
    const expected = ['/axes/impact_speed/values', '/replicates/count', '/execution/max_attempts'];
    assert.deepEqual(pointers.sort(), [...expected].sort());
    for (const pointer of expected) {
      const field = page.locator(`#document-tree .field.invalid[data-pointer="${pointer}"]`);
      assert.equal(await field.count(), 1, pointer);
      assert.match(await field.locator(':scope > .message').first().textContent(), /must/, pointer);
    }
    assert.equal(await page.locator('#document-tree .field.invalid').count(), expected.length);
    assert.equal((await service.get('/api/studies')).total, storedBefore, 'nothing stored');
    // The form shows the service's messages at its own fields too.
    assert.match(await page.textContent('#form-replicates-message'), /must/);

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
    const study = smallStudy('to cancel',
      { speeds: [0.01, 0.05, 0.1, 0.2, 0.3], primaries: [128], gammas: [0.001, 0.01], replicates: 12 });
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
    await until(async () => (await service.get(`/api/studies/${id}/progress`)).complete,
      { what: 'running cases to end' });
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
    await page.fill('#study-json', JSON.stringify(smallStudy('with token',
      { speeds: [0.01], primaries: [8], gammas: [0.001], replicates: 1 })));
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
