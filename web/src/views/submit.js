// Submitting a study: a form for the common physical study (submit_form.js) beside the study's JSON,
// which holds the rest; each follows the other as the user types. The page starts from the
// service's default study (GET /api/templates) or a small reduced-units sweep, its fields named by
// the service's case fields (GET /api/case-fields); a study can also be pasted or read from a file.
// It is sent as application/json; the service's validation errors are
// shown at the form fields and in a view of the submitted document at the fields their JSON
// pointers name, and listed.
import { ApiError, getJson, postJson } from '../api.js';
import { el, replaceChildren, select } from '../dom.js';
import { escapeToken, nearestPresent } from '../json_pointer.js';
import { createStudyForm } from './submit_form.js';

const kReducedExample = {
  name: 'small speed sweep',
  description: 'Ballistic clusters of 16 primaries at three speeds, in reduced units',
  base: {
    cluster: { generator: { method: 'ballistic', primaries: 16 } },
    material: { gamma_over_kn: 0.001 },
    run: { time_limit: 20000 },
  },
  axes: { impact_speed: { values: [0.005, 0.02, 0.08] } },
  replicates: { count: 2, seed: 1 },
  execution: { max_attempts: 2, case_wall_time: 600 },
};

// The document as nested fields, each marked with its JSON pointer; messages attach to the field
// their pointer names, or to its nearest ancestor present in the document.
function documentTree(document, messagesByPointer) {
  function field(key, value, pointer) {
    const messages = messagesByPointer.get(pointer) || [];
    const isContainer = value !== null && typeof value === 'object';
    const children = isContainer
      ? Object.entries(value).map(([k, v]) => field(k, v, `${pointer}/${escapeToken(k)}`))
      : [];
    return el('div', { class: messages.length ? 'field invalid' : 'field', dataset: { pointer } },
      el('span', { class: 'key' }, key === null ? '(document)' : `${key}:`), ' ',
      isContainer ? '' : el('span', { class: 'value' }, JSON.stringify(value)),
      messages.map((message) => el('span', { class: 'message' }, message)), children);
  }
  return field(null, document, '');
}

function showViolations(output, document, body, form) {
  const byPointer = new Map();
  for (const violation of body.violations || []) {
    form.markViolation(violation.pointer || '', violation.message);
    const at = nearestPresent(document, violation.pointer || '');
    const text = at === violation.pointer ? violation.message : `${violation.pointer}: ${violation.message}`;
    byPointer.set(at, [...(byPointer.get(at) || []), text]);
  }
  replaceChildren(output, el('p', { class: 'errors', id: 'submit-error' }, body.error || 'the study is not valid'),
    el('ul', { class: 'errors', id: 'violations' }, (body.violations || []).map((v) =>
      el('li', { dataset: { pointer: v.pointer } }, el('code', {}, v.pointer || '(document)'), ' ', v.message))),
    el('div', { class: 'tree', id: 'document-tree' }, documentTree(document, byPointer)));
}

async function templates() {
  const answer = await getJson('/api/templates').catch(() => ({ items: [] }));
  return [...answer.items.map((item) => ({ label: `${item.name} (${item.file})`, document: item.document })),
    { label: 'a small sweep in reduced units', document: kReducedExample }];
}

export async function showSubmit(view) {
  const [choices, caseFields] = await Promise.all([templates(),
    getJson('/api/case-fields').then((answer) => answer.items, () => [])]);
  let document = structuredClone(choices[0].document);
  const text = el('textarea', { id: 'study-json', spellcheck: 'false' });
  const jsonMessage = el('p', { class: 'field-message error', id: 'study-json-message', 'aria-live': 'polite' });
  const output = el('div', { id: 'submit-output' });
  const form = createStudyForm({ current: () => document, caseFields, changed: (changed) => {
    text.value = JSON.stringify(changed, null, 2);
    jsonMessage.textContent = '';
  } });
  const load = (chosen) => {
    document = chosen;
    text.value = JSON.stringify(document, null, 2);
    jsonMessage.textContent = '';
    form.show(document);
    text.dispatchEvent(new Event('input'));
  };
  // The JSON view as the user types: the form follows while it is JSON.
  text.addEventListener('input', () => {
    try {
      const parsed = JSON.parse(text.value);
      if (parsed === null || typeof parsed !== 'object' || Array.isArray(parsed))
        throw new Error('a study is a JSON object');
      document = parsed;
      jsonMessage.textContent = '';
      form.lock(false);
      form.show(document);
    } catch (error) {
      jsonMessage.textContent = `not JSON: ${error.message} (the form waits until it is)`;
      form.lock(true);
    }
  });
  const file = el('input', { type: 'file', id: 'study-file', accept: '.json,application/json' });
  file.addEventListener('change', async () => {
    if (!file.files.length) return;
    text.value = await file.files[0].text();
    text.dispatchEvent(new Event('input'));
  });
  const note = el('span', { class: 'note', id: 'submit-note' });
  const updateNote = () => {
    const count = form.problems();
    note.textContent = count
      ? `${count} field${count > 1 ? 's need' : ' needs'} attention (marked above); the service checks the rest.` : '';
  };
  form.node.addEventListener('input', updateNote);
  form.node.addEventListener('change', updateNote);
  text.addEventListener('input', updateNote);
  const submit = () => submitStudy(text.value, output, form).then(updateNote);
  const chooser = select(choices.map((choice, i) => [String(i), choice.label]), '0',
    (i) => load(structuredClone(choices[Number(i)].document)), { id: 'choose-template' });
  replaceChildren(view, el('h1', {}, 'Submit a study'),
    el('p', { class: 'controls' }, el('label', {}, 'Start from ', chooser), ' or read a study from a file: ', file),
    el('div', { class: 'submit-layout' }, form.node,
      el('div', { class: 'json-view' }, el('h2', {}, 'The study as JSON (schemas/study.schema.json)'),
        el('p', { class: 'note' }, 'Everything the form does not show (model, run, classification, further axes) is ' +
          'edited here; the form follows.'),
        text, jsonMessage)),
    el('p', {}, el('button', { id: 'submit-study', onclick: submit }, 'Submit'), ' ', note), output);
  load(document);
  updateNote();
  return null;
}

async function submitStudy(bodyText, output, form) {
  let document;
  try {
    document = JSON.parse(bodyText);
  } catch (error) {
    replaceChildren(output, el('p', { class: 'errors', id: 'submit-error' }, `not JSON: ${error.message}`));
    return;
  }
  try {
    const { status, body } = await postJson('/api/studies', bodyText);
    replaceChildren(output, el('p', { id: 'submit-receipt' }, status === 201 ? 'Submitted: ' : 'Submitted before: ',
      el('a', { href: `/?study=${body.id}`, 'data-nav': true }, `study ${body.id}`),
      ` (${body.cases} cases, ${body.new_cases} new, ${body.already_done} already done).`));
  } catch (error) {
    if (error instanceof ApiError && error.body) showViolations(output, document, error.body, form);
    else replaceChildren(output, el('p', { class: 'errors', id: 'submit-error' }, error.message));
  }
}
