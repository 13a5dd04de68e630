// Submitting a study: JSON pasted or read from a file, sent as application/json. The service's
// validation errors are shown next to the fields they name (their JSON pointers) in a view of the
// submitted document, and listed.
import { ApiError, postJson } from '../api.js';
import { el, replaceChildren } from '../dom.js';

const kExample = {
  name: 'small speed sweep',
  description: 'Ballistic clusters of 16 primaries at three speeds',
  base: {
    cluster: { generator: { method: 'ballistic', primaries: 16 } },
    material: { gamma_over_kn: 0.001 },
    run: { time_limit: 20000 },
  },
  axes: { impact_speed: { values: [0.005, 0.02, 0.08] } },
  replicates: { count: 2, seed: 1 },
  execution: { max_attempts: 2, case_wall_time: 600 },
};

const escapeToken = (token) => token.replaceAll('~', '~0').replaceAll('/', '~1');

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

function nearestPresent(document, pointer) {
  let path = pointer;
  const exists = (p) => {
    try {
      return p.split('/').slice(1).reduce((node, token) => {
        const key = token.replaceAll('~1', '/').replaceAll('~0', '~');
        if (node === null || typeof node !== 'object' || !(key in node)) throw new Error('absent');
        return node[key];
      }, document) !== undefined;
    } catch {
      return false;
    }
  };
  while (path && !exists(path)) path = path.slice(0, path.lastIndexOf('/'));
  return path;
}

function showViolations(output, document, body) {
  const byPointer = new Map();
  for (const violation of body.violations || []) {
    const at = nearestPresent(document, violation.pointer || '');
    const text = at === violation.pointer ? violation.message : `${violation.pointer}: ${violation.message}`;
    byPointer.set(at, [...(byPointer.get(at) || []), text]);
  }
  const tree = documentTree(document, byPointer);
  replaceChildren(output, el('p', { class: 'errors', id: 'submit-error' }, body.error || 'the study is not valid'),
    el('ul', { class: 'errors', id: 'violations' }, (body.violations || []).map((v) =>
      el('li', { dataset: { pointer: v.pointer } }, el('code', {}, v.pointer || '(document)'), ' ', v.message))),
    el('div', { class: 'tree', id: 'document-tree' }, tree));
}

export async function showSubmit(view) {
  const text = el('textarea', { id: 'study-json', spellcheck: 'false' }, JSON.stringify(kExample, null, 2));
  const file = el('input', { type: 'file', id: 'study-file', accept: '.json,application/json' });
  const output = el('div', { id: 'submit-output' });
  file.addEventListener('change', async () => {
    if (file.files.length) text.value = await file.files[0].text();
  });
  const submit = async () => {
    let document;
    try {
      document = JSON.parse(text.value);
    } catch (error) {
      replaceChildren(output, el('p', { class: 'errors', id: 'submit-error' }, `not JSON: ${error.message}`));
      return;
    }
    try {
      const { status, body } = await postJson('/api/studies', text.value);
      replaceChildren(output, el('p', { id: 'submit-receipt' }, status === 201 ? 'Submitted: ' : 'Submitted before: ',
        el('a', { href: `/?study=${body.id}`, 'data-nav': true }, `study ${body.id}`),
        ` (${body.cases} cases, ${body.new_cases} new, ${body.already_done} already done).`));
    } catch (error) {
      if (error instanceof ApiError && error.body) showViolations(output, document, error.body);
      else replaceChildren(output, el('p', { class: 'errors', id: 'submit-error' }, error.message));
    }
  };
  replaceChildren(view, el('h1', {}, 'Submit a study'),
    el('p', {}, 'Paste a study (schemas/study.schema.json) or read one from a file: ', file),
    text, el('p', {}, el('button', { id: 'submit-study', onclick: submit }, 'Submit')), output);
  return null;
}
