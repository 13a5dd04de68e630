// The study's cases, filtered by status, outcome and any axis value and paged by the server
// (GET /api/studies/ID/case-table); the filters and the page are kept in the URL. The next page is
// asked for while the user reads this one, so that turning to it shows it at once.
import { getJson } from '../api.js';
import { el, formatNumber, replaceChildren, select, table } from '../dom.js';
import { valueKey } from '../series.js';

const kPageSize = 25;
const kStatuses = ['queued', 'running', 'done', 'failed', 'cancelled'];
const kOutcomes = ['stick', 'bounce', 'break-up', 'undetermined'];

// A result's flags in words (docs/IMPACT.md section 5); empty without a result.
function flagsText(c) {
  const flags = [];
  if (c.fractured_on_wall) flags.push('fractured on wall');
  if (c.small_strain_exceeded) flags.push('small strain exceeded');
  if (c.outcome && c.small_strain_exceeded === null) flags.push('small strain unchecked');
  return flags.join(', ');
}

function columns(axes, names) {
  return [
    { label: 'Case', value: (c) => el('a', { href: `/?case=${c.id}`, 'data-nav': true }, String(c.id)) },
    ...axes.map((axis) => ({ label: names.label(axis.name), value: (c) => formatNumber(c.grid_point[axis.name], 4),
      numeric: true })),
    { label: 'Replicate', value: (c) => c.replicate, numeric: true },
    { label: 'Status', value: (c) => c.status },
    { label: 'Outcome', value: (c) => c.outcome || '–' },
    { label: 'Restitution', value: (c) => formatNumber(c.restitution), numeric: true },
    { label: 'Retained', value: (c) => formatNumber(c.retained_mass_fraction), numeric: true },
    { label: 'Fragments', value: (c) => formatNumber(c.fragment_count), numeric: true },
    { label: 'Damage', value: (c) => formatNumber(c.damage_ratio), numeric: true },
    { label: 'Flags', value: flagsText, className: 'flags' },
    { label: 'Attempts', value: (c) => c.attempts, numeric: true },
    { label: 'Error', value: (c) => c.error || '', className: 'error' },
  ];
}

export function createCaseTable({ state, studyId }) {
  const filters = el('div', { class: 'controls', id: 'case-filters' });
  const holder = el('div', { id: 'case-table' });
  const pager = el('div', { class: 'pager', id: 'case-pager' });
  const node = el('div', {}, filters, holder, pager);
  let axes = [];
  let names = null;
  let request = 0;

  const change = (changes) => {
    state.set({ ...changes, page: changes.page === undefined ? null : changes.page });
    load(axes, names);
  };
  const anyOf = (values, labels = values) => [['', 'any'], ...values.map((v, i) => [v, labels[i]])];

  function drawFilters() {
    replaceChildren(filters,
      el('label', {}, 'Status ', select(anyOf(kStatuses), state.get('f.status', ''),
        (v) => change({ 'f.status': v }), { id: 'filter-status' })),
      el('label', {}, 'Outcome ', select(anyOf(kOutcomes), state.get('f.outcome', ''),
        (v) => change({ 'f.outcome': v }), { id: 'filter-outcome' })),
      axes.map((axis) => el('label', {}, `${names.label(axis.name)} `,
        select(anyOf(axis.values.map(valueKey), axis.values.map((v) => formatNumber(v, 4))),
          state.get(`f.axis.${axis.name}`, ''),
          (v) => change({ [`f.axis.${axis.name}`]: v }), { dataset: { filterAxis: axis.name } }))));
  }

  // Pages asked for ahead (the page after the one shown), by URL; forgotten when the study's
  // cases change.
  let ahead = new Map();
  function pageUrl(page) {
    const search = new URLSearchParams({ limit: kPageSize, offset: page * kPageSize });
    if (state.get('f.status')) search.set('status', state.get('f.status'));
    if (state.get('f.outcome')) search.set('outcome', state.get('f.outcome'));
    for (const [axis, value] of Object.entries(state.withPrefix('f.axis.'))) search.set(`axis.${axis}`, value);
    return `/api/studies/${studyId}/case-table?${search}`;
  }
  const askAhead = (url) => {
    const answer = getJson(url);
    answer.catch(() => ahead.delete(url));
    ahead = new Map([[url, answer]]);
  };

  // The page of cases the URL asks for: fetched with no need of the study's axes, so that it can
  // be asked for together with the grid statistics.
  function fetchPage() {
    const url = pageUrl(Number(state.get('page', 0)));
    return ahead.get(url) || getJson(url);
  }

  // Draws the page of cases the URL asks for, of a study with `studyAxes` (GET .../grid) that
  // `axisNames` names (axis_names.js AxisNames).
  async function load(studyAxes, axisNames, pending = fetchPage()) {
    axes = studyAxes;
    names = axisNames;
    drawFilters();
    const page = Number(state.get('page', 0));
    const mine = ++request;
    const result = await pending;
    if (mine !== request) return;
    holder.dataset.total = result.total;
    replaceChildren(holder, table(columns(axes, names), result.items));
    const first = result.total === 0 ? 0 : page * kPageSize + 1;
    replaceChildren(pager,
      el('button', { id: 'page-previous', disabled: page === 0, onclick: () => change({ page: page - 1 || null }) },
        '← previous'),
      el('span', { id: 'page-range' }, `${first}–${page * kPageSize + result.items.length} of ${result.total}`),
      el('button', { id: 'page-next', disabled: (page + 1) * kPageSize >= result.total,
        onclick: () => change({ page: page + 1 }) }, 'next →'));
    if ((page + 1) * kPageSize < result.total) askAhead(pageUrl(page + 1));
  }
  // Drops the pages asked for ahead (the study's cases changed).
  const forget = () => { ahead = new Map(); };
  return { node, load, fetchPage, forget };
}
