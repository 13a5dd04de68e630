// A study: its description, progress and axes, plots of the server's per-grid-point statistics,
// once it has results the correlation and table panels, and its cases. Every choice (outcome, x axis, slice,
// table filters, page) is kept in the URL, so that the address reproduces the view.
import { getJson, postJson } from '../api.js';
import { el, formatDuration, formatNumber, replaceChildren, select, table } from '../dom.js';
import { defaultXAxis, derivedXChoices, sliceAxes, valueKey } from '../series.js';
import { AxisNames } from '../axis_names.js';
import { progressBar, studyState } from '../progress.js';
import { Correlations, loadCorrelationSummary } from '../correlations.js';
import { createPlots } from './study_plots.js';
import { createCaseTable } from './case_table.js';
import { tablesPanel } from './study_tables.js';

const kRefreshMs = 3000;
const kOutcomes = ['break-up', 'stick', 'bounce', 'undetermined'];

// The view's choices, read from and written back to the URL.
class ViewState {
  constructor(parameters) {
    this.parameters = new URLSearchParams(parameters);
  }
  get(name, fallback = null) {
    return this.parameters.has(name) ? this.parameters.get(name) : fallback;
  }
  set(changes) {
    for (const [name, value] of Object.entries(changes)) {
      if (value === null || value === undefined || value === '') this.parameters.delete(name);
      else this.parameters.set(name, value);
    }
    history.replaceState(null, '', `/?${this.parameters.toString()}`);
  }
  withPrefix(prefix) {
    const found = {};
    for (const [name, value] of this.parameters) if (name.startsWith(prefix)) found[name.slice(prefix.length)] = value;
    return found;
  }
  // Names each axis in the address (x, s.AXIS, f.axis.AXIS) as the study does, whether the address
  // names it so, by its alias or by its pointer (axis_names.js AxisNames.find): an address keeps
  // working whichever way the study and the address name them.
  nameAxesAs(names) {
    const renamed = (reference) => names.find(reference) || reference;
    const before = this.parameters.toString();
    this.parameters = new URLSearchParams([...this.parameters].map(([name, value]) => {
      if (name === 'x') return [name, renamed(value)];
      const prefix = ['s.', 'f.axis.'].find((p) => name.startsWith(p));
      return prefix ? [prefix + renamed(name.slice(prefix.length)), value] : [name, value];
    }));
    if (this.parameters.toString() !== before) history.replaceState(null, '', `/?${this.parameters.toString()}`);
  }
}

function progressText(progress) {
  const c = progress.counts;
  const parts = [`${c.done} done`, `${c.failed} failed`, `${c.running} running`, `${c.queued} queued`];
  if (c.cancelled) parts.push(`${c.cancelled} cancelled`);
  const rate = progress.cases_per_hour > 0 ? `, ${formatNumber(progress.cases_per_hour, 3)} cases/h` : '';
  const left = progress.complete ? '' : `, ${formatDuration(progress.seconds_left)} left`;
  return `${progress.total} cases: ${parts.join(', ')}${rate}${left}`;
}

// The study's axes (GET /api/studies/ID: axes) with their values, the search's axis (docs/ADAPTIVE.md)
// by its range and the number of values run so far (`gridAxes`, GET /api/studies/ID/grid: axes).
function axesTable(studyAxes, gridAxes, names) {
  const valuesText = (axis) => {
    if (axis.role !== 'search') return axis.values.map((value) => formatNumber(value, 4)).join(', ');
    const run = (gridAxes.find((other) => other.name === axis.name) || { values: [] }).values.length;
    const [from, to] = axis.range.map((value) => formatNumber(value, 4));
    return `searched over ${from}–${to}: ${run} value${run === 1 ? '' : 's'} run`;
  };
  return table([
    { label: 'Axis', value: (axis) => names.label(axis.name) },
    { label: 'Values', value: valuesText },
  ], studyAxes, { id: 'axes-table' });
}

const kUnitsText = { physical: 'SI units', reduced: 'reduced units (d, m, τ)',
  mixed: 'units that differ between grid points' };

function header(study, { onCancel }) {
  const state = studyState(study);
  const cancel = state === 'running' || state === 'queued'
    ? el('button', { class: 'danger', id: 'cancel-study', onclick: onCancel }, 'Cancel study') : null;
  return el('section', {},
    el('h1', { id: 'study-name' }, study.name),
    el('p', { class: 'description', id: 'study-description' }, study.description),
    el('p', {}, `Study ${study.id}, `, el('span', { id: 'study-state', class: `study-state ${state}` }, state),
      `, in ${kUnitsText[study.units.system] || study.units.system}. `, cancel),
    el('div', { class: 'progress-line' }, progressBar(study.progress), el('span', { id: 'progress' },
      progressText(study.progress))));
}

function controls(state, grid, names, onChange) {
  const { axes } = grid;
  const xAxis = state.get('x', defaultXAxis(axes, names));
  const numericAxes = axes.filter((axis) => axis.values.length > 1 && axis.values.every((v) => typeof v === 'number'))
    .concat(derivedXChoices(grid, names).map((name) => ({ name })));
  const slices = sliceAxes(axes, xAxis, names).map((axis) => el('label', {}, `${names.label(axis.name)} `,
    select(axis.values.map((v) => [valueKey(v), formatNumber(v, 4)]),
      state.get(`s.${axis.name}`, valueKey(axis.values[0])),
      (value) => onChange({ [`s.${axis.name}`]: value }), { dataset: { slice: axis.name } })));
  return el('div', { class: 'controls', id: 'plot-controls' },
    el('label', {}, 'Outcome ', select(kOutcomes.map((o) => [o, o]), state.get('outcome', 'break-up'),
      (value) => onChange({ outcome: value }), { id: 'choose-outcome' })),
    el('label', {}, 'Along ', select(numericAxes.map((a) => [a.name, names.label(a.name)]), xAxis,
      (value) => onChange({ x: value }), { id: 'choose-x' })),
    slices);
}

// The parts a study has once it has results: the lookup-table links, and the correlations, asked
// for once the page is drawn (fitting a large study the first time takes seconds, and the page
// does not wait for it). A study without results has nothing to fit or tabulate (the correlations
// answer 404, the tables 409): neither is shown then. While the study runs the correlations are
// asked again when results first arrive, at most every kCorrelationsRefreshMs while more arrive,
// and once more when it ends.
const kCorrelationsRefreshMs = 30000;

function createResultParts(id, { plots, tablesHolder, searched, redraw, stopped }) {
  let asked = null;
  function ask(study) {
    if (!asked) replaceChildren(tablesHolder, tablesPanel(id, { searched }));
    asked = { done: study.progress.counts.done, complete: study.progress.complete, at: Date.now() };
    loadCorrelationSummary(id).then((summary) => {
      if (stopped()) return;
      plots.setCorrelations(summary ? new Correlations(id, summary) : null);
      redraw();
    }).catch(() => {});
  }
  // Asks when `study` has results the last answer did not see and it is time to.
  return (study) => {
    const { counts: { done }, complete } = study.progress;
    if (done === 0) return;
    const due = done !== asked?.done && Date.now() - (asked?.at ?? 0) >= kCorrelationsRefreshMs;
    if (!asked || (complete && !asked.complete) || due) ask(study);
  };
}

// The grid statistics change only with the cases' states and results.
const countsKey = (study) => JSON.stringify(study.progress.counts);

export async function showStudy(view, parameters, { showNotice }) {
  const state = new ViewState(parameters);
  const id = Number(state.get('study'));
  const caseTable = createCaseTable({ state, studyId: id });
  // The first page of cases is asked for with the study, unless the address filters it by an axis
  // (which the service knows by the study's name for it only, known with the study).
  const filtered = Object.keys(state.withPrefix('f.axis.')).length > 0;
  const earlyCases = filtered ? null : caseTable.fetchPage();
  earlyCases?.catch(() => {});
  const [study, grid] = await Promise.all([getJson(`/api/studies/${id}`), getJson(`/api/studies/${id}/grid`)]);
  const names = new AxisNames(study.axes);
  state.nameAxesAs(names);
  const firstCases = earlyCases || caseTable.fetchPage();
  let current = { study, grid };
  let timer = null;
  let stopped = false;

  const onCancel = async () => {
    try {
      await postJson(`/api/studies/${id}/cancel`);
      await refresh();
    } catch (error) {
      showNotice(`cancel failed: ${error.message}`);
    }
  };
  const plots = createPlots({ state });
  const tablesHolder = el('div');
  const controlsHolder = el('div');
  const drawControls = () => replaceChildren(controlsHolder, controls(state, current.grid, names, (changes) => {
    state.set(changes);
    drawControls();
    if (Object.keys(changes).every((name) => name === 'outcome')) plots.drawOutcome(current.grid, names);
    else plots.draw(current.grid, names);
  }));
  const headerHolder = el('div', {}, header(study, { onCancel }));
  const axesHolder = el('div', {}, axesTable(study.axes, grid.axes, names));
  replaceChildren(view, headerHolder,
    el('h2', {}, 'Axes'), axesHolder,
    el('h2', {}, 'Outcomes'), controlsHolder, plots.node, tablesHolder,
    el('h2', {}, 'Cases'), caseTable.node);
  drawControls();
  await Promise.all([plots.draw(grid, names), caseTable.load(grid.axes, names, firstCases)]);
  const searched = study.axes.some((axis) => names.searched(axis.name));
  const askResultParts = createResultParts(id, { plots, tablesHolder, searched,
    redraw: () => plots.drawOutcome(current.grid, names), stopped: () => stopped });
  askResultParts(study);

  async function refresh() {
    const [nextStudy, nextGrid] = await Promise.all([getJson(`/api/studies/${id}`),
      getJson(`/api/studies/${id}/grid`)]);
    if (stopped) return;
    const gridChanged = countsKey(nextStudy) !== countsKey(current.study);
    current = { study: nextStudy, grid: nextGrid };
    replaceChildren(headerHolder, header(nextStudy, { onCancel }));
    askResultParts(nextStudy);
    if (!gridChanged) return;
    caseTable.forget();
    replaceChildren(axesHolder, axesTable(study.axes, nextGrid.axes, names));
    await Promise.all([plots.draw(nextGrid, names), caseTable.load(nextGrid.axes, names)]);
  }
  async function poll() {
    try {
      await refresh();
    } catch (error) {
      showNotice(`cannot reach the service: ${error.message}`);
    }
    if (!stopped && !current.study.progress.complete) timer = setTimeout(poll, kRefreshMs);
  }
  if (!study.progress.complete) timer = setTimeout(poll, kRefreshMs);
  return () => {
    stopped = true;
    clearTimeout(timer);
  };
}
