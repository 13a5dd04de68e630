// The submit form: the common physical study's fields (submit_fields.js), each checked as the user
// types, its message beside it, and written into the study document when valid; the document's
// other fields are edited in the JSON view (submit.js), which the form follows. A material field
// is only offered for a physical study (the reduced material is edited in the JSON view).
import { el, replaceChildren, select } from '../dom.js';
import { escapeToken, getAt, removeAt, setAt } from '../json_pointer.js';
import { unitText } from '../units.js';
import {
  caseFieldNames, fieldText, kFormFields, kGeneratorFields, kWallPointer, readField, unusualValue,
} from './submit_fields.js';

const kWalls = [[true, 'adhesive (JKR, the primaries’ material)'], [false, 'without adhesion (Hertz)']];
const isPhysical = (document) => getAt(document, '/base/units') === 'physical';
const byId = (id) => kFormFields.find((field) => field.id === id);

// How many cases the document's axes and replicates make (ranges count `count` values).
export function caseCount(document) {
  const axes = Object.values((document && document.axes) || {});
  const sizes = axes.map((axis) => (Array.isArray(axis.values) ? axis.values.length : Number(axis.count) || 1));
  return sizes.reduce((product, size) => product * size, 1) * (Number(getAt(document, '/replicates/count')) || 1);
}

// Where the document keeps a field's value. An axis field's values lie under the axis's alias
// (field.pointer, /axes/impact_speed/values) or, where the study names the axis by the pointer of
// the case field instead (docs/ORCHESTRATOR.md), under that (/axes/~1impact~1speed/values).
function pointerIn(document, field) {
  if (!field.base) return field.pointer;
  const byPointer = `/axes/${escapeToken(field.base.slice('/base'.length))}`;
  return getAt(document, byPointer) === undefined ? field.pointer : `${byPointer}/values`;
}

// Writes a field's value; an axis replaces the one value the base may set, and the generator drops
// the fields the new one does not take and adds those it needs.
function writeField(document, field, value) {
  if (field.id !== 'generator') {
    setAt(document, pointerIn(document, field), value);
    if (field.base) removeAt(document, field.base);
    return;
  }
  for (const [other, fields] of Object.entries(kGeneratorFields))
    if (other !== value) for (const name of fields) removeAt(document, `/base/cluster/generator/${name}`);
  setAt(document, field.pointer, value);
  for (const needed of kFormFields.filter((f) => f.only === value))
    if (getAt(document, needed.pointer) === undefined) setAt(document, needed.pointer, needed.initial);
}

// A field's row: label, input, unit and message (label and unit shown by fillForm). `onInput(field)`
// runs as the user types.
function fieldRow(field, onInput) {
  const id = `form-${field.id}`;
  const input = field.kind === 'choice' ? select(field.options, field.options[0][0], () => onInput(field), { id })
    : el(field.id === 'description' ? 'textarea' : 'input',
      { id, type: 'text', spellcheck: 'false', oninput: () => onInput(field) });
  const unit = el('span', { class: 'unit' });
  const message = el('span', { class: 'field-message', id: `${id}-message`, 'aria-live': 'polite' });
  const label = el('label', { for: id });
  const row = el('div', { class: 'form-row', dataset: { pointer: field.pointer } },
    label, el('span', { class: 'input' }, input, unit), message);
  return { field, row, label, input, unit, message };
}

// The walls: two boxes that write the /wall/adhesive axis (at least one is needed).
function wallsRow(onChange) {
  const boxes = kWalls.map(() => el('input', { type: 'checkbox', onchange: () => onChange(chosen()) }));
  const chosen = () => kWalls.filter((_, i) => boxes[i].checked).map(([value]) => value);
  const message = el('span', { class: 'field-message', id: 'form-walls-message', 'aria-live': 'polite' });
  const checks = kWalls.map(([, label], i) => el('label', { class: 'check' }, boxes[i], ` ${label}`));
  const row = el('div', { class: 'form-row', dataset: { pointer: kWallPointer } },
    el('span', { class: 'label' }, 'walls'), el('span', { class: 'input' }, checks), message);
  const fill = (walls) => kWalls.forEach(([value], i) => { boxes[i].checked = walls.includes(value); });
  return { row, message, fill, chosen };
}

function showMessage(entry, error, note) {
  entry.message.textContent = error || note || '';
  entry.message.className = `field-message ${error ? 'error' : 'note'}`;
  entry.input?.setAttribute('aria-invalid', String(Boolean(error)));
}

// An axis's values, or the one value the base sets; undefined for an axis given as a range.
function valueOf(document, field) {
  const value = getAt(document, pointerIn(document, field));
  if (value !== undefined || !field.base) return value;
  const base = getAt(document, field.base);
  return base === undefined ? undefined : [base];
}

function isRange(document, field) {
  const pointer = pointerIn(document, field);
  return field.base && getAt(document, pointer) === undefined &&
    getAt(document, pointer.slice(0, pointer.lastIndexOf('/'))) !== undefined;
}

// Shows the document's values in the form's fields (leaving alone the one being typed in), the
// walls, the note on a reduced material and the number of cases; labels and units of the case fields
// as the service names them (caseFields: GET /api/case-fields).
function fillForm(document, { entries, walls, materialNote, summary, caseFields }) {
  const physical = isPhysical(document);
  const method = getAt(document, '/base/cluster/generator/method') || 'ballistic';
  for (const { field, row, label, input, unit } of entries.values()) {
    const names = caseFieldNames(field, caseFields, physical);
    label.textContent = names.label;
    unit.textContent = unitText(names.unit);
    row.hidden = Boolean(field.only && field.only !== method);
    input.disabled = Boolean((field.material && !physical) || isRange(document, field));
    input.title = isRange(document, field) ? 'a range of values: edit it in the JSON view' : '';
    if (input !== globalThis.document.activeElement)
      input.value = field.kind === 'choice' ? method : fieldText(field, valueOf(document, field));
  }
  walls.fill(getAt(document, kWallPointer) || [getAt(document, '/base/wall/adhesive') ?? true]);
  materialNote.textContent = physical ? ''
    : 'This study is in reduced units: its material (γ/k_n, ν) is edited in the JSON view.';
  replaceChildren(summary,
    `${caseCount(document)} cases: every combination of the axes' values, times the replicates.`);
}

// `current()` gives the study document, `changed(document)` is called after the form wrote into it;
// `caseFields`: the service's case fields (GET /api/case-fields: items), empty when not known.
export function createStudyForm({ current, changed, caseFields = [] }) {
  const entries = new Map();
  const problems = new Set();
  const check = (entry, read) => {
    (read.error ? problems.add(entry.field.id) : problems.delete(entry.field.id));
    showMessage(entry, read.error, read.error ? null : unusualValue(entry.field, read.value));
  };
  const onInput = (field) => {
    const entry = entries.get(field.id);
    const read = readField(field, entry.input.value);
    check(entry, read);
    if (read.error) return;
    const document = current();
    writeField(document, field, read.value);
    changed(document);
    fill(document);
  };
  const walls = wallsRow((values) => {
    const error = values.length ? null : 'choose at least one wall';
    (error ? problems.add('walls') : problems.delete('walls'));
    showMessage(walls, error, null);
    if (error) return;
    const document = current();
    setAt(document, kWallPointer, values);
    removeAt(document, '/base/wall/adhesive');
    changed(document);
    fill(document);
  });
  const group = (title, ids, extra = []) => el('fieldset', {}, el('legend', {}, title), ids.map((id) => {
    const entry = fieldRow(byId(id), onInput);
    entries.set(id, entry);
    return entry.row;
  }), extra);
  const parts = { entries, walls, caseFields, materialNote: el('p', { class: 'note', id: 'form-material-note' }),
    summary: el('p', { class: 'note', id: 'form-summary' }) };
  const node = el('form', { class: 'study-form', id: 'study-form', onsubmit: (event) => event.preventDefault() },
    group('Study', ['name', 'description']),
    group('Material of the primaries (SI)', ['youngs_modulus', 'poisson_ratio', 'density', 'surface_energy',
      'diameter'], [parts.materialNote]),
    group('Sweep', ['speeds', 'primaries', 'generator', 'fractal_dimension', 'prefactor'], [walls.row]),
    group('Replicates', ['replicates', 'seed']), parts.summary);
  const fill = (document) => fillForm(document, parts);

  return {
    node,
    // Shows `document` in the fields and checks every field offered.
    show(document) {
      fill(document);
      problems.clear();
      for (const entry of entries.values())
        if (entry.row.hidden || entry.input.disabled) showMessage(entry, null, null);
        else check(entry, readField(entry.field, entry.input.value));
      showMessage(walls, null, null);
    },
    problems: () => problems.size,
    // Locks the form while the JSON view is not JSON, so that no field overwrites what the user is
    // typing there.
    lock(locked) {
      for (const fieldset of node.querySelectorAll('fieldset')) fieldset.disabled = locked;
    },
    // Shows a message of the service at the form field whose pointer is `pointer` or lies above
    // it; false when no shown field is there.
    markViolation(pointer, message) {
      const names = ({ field }) => [field.pointer, pointerIn(current(), field)]
        .some((at) => pointer === at || pointer.startsWith(`${at}/`));
      const entry = [...entries.values()].find(names);
      if (!entry || entry.row.hidden) return false;
      problems.add(entry.field.id);
      showMessage(entry, message, null);
      return true;
    },
  };
}
