// A study: its description, progress and axes, plots of the server's per-grid-point statistics,
// once it has results the correlation and table panels, and its cases. Every choice (outcome, x axis, slice,
// table filters, page) is kept in the URL, so that the address reproduces the view.
import { getJson, postJson } from '../api.js';
import { el, formatDuration, formatNumber, replaceChildren, select, table } from '../dom.js';
import { axisLabel, defaultXAxis, derivedXChoices, sliceAxes, valueKey } from '../series.js';
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
}

function progressText(progress) {
  const c = progress.counts;
  const parts = [`${c.done} done`, `${c.failed} failed`, `${c.running} running`, `${c.queued} queued`];
  if (c.cancelled) parts.push(`${c.cancelled} cancelled`);
  const rate = progress.cases_per_hour > 0 ? `, ${formatNumber(progress.cases_per_hour, 3)} cases/h` : '';
  const left = progress.complete ? ', complete' : `, ${formatDuration(progress.seconds_left)} left`;
  return `${progress.total} cases: ${parts.join(', ')}${rate}${left}`;
}

function axesTable(axes) {
  return table([
    { label: 'Axis', value: (axis) => axisLabel(axis.name) },
    { label: 'Values', value: (axis) => axis.values.map((value) => formatNumber(value, 4)).join(', ') },
  ], axes, { id: 'axes-table' });
}

function header(study, { onCancel }) {
  const progressLine = el('p', { id: 'progress' }, progressText(study.progress));
  const cancel = study.status === 'active' && !study.progress.complete
    ? el('button', { class: 'danger', id: 'cancel-study', onclick: onCancel }, 'Cancel study') : null;
  return {
    node: el('section', {},
      el('h1', { id: 'study-name' }, study.name),
      el('p', { class: 'description', id: 'study-description' }, study.description),
      el('p', {}, `Study ${study.id}, ${study.status}. `, cancel), progressLine),
    progressLine,
  };
}

function controls(state, grid, onChange) {
  const { axes } = grid;
  const xAxis = state.get('x', defaultXAxis(axes));
  const numericAxes = axes.filter((axis) => axis.values.length > 1 && axis.values.every((v) => typeof v === 'number'))
    .concat(derivedXChoices(grid).map((name) => ({ name })));
  const slices = sliceAxes(axes, xAxis).map((axis) => el('label', {}, `${axisLabel(axis.name)} `,
    select(axis.values.map((v) => [valueKey(v), formatNumber(v, 4)]), state.get(`s.${axis.name}`, valueKey(axis.values[0])),
      (value) => onChange({ [`s.${axis.name}`]: value }), { dataset: { slice: axis.name } })));
  return el('div', { class: 'controls', id: 'plot-controls' },
    el('label', {}, 'Outcome ', select(kOutcomes.map((o) => [o, o]), state.get('outcome', 'break-up'),
      (value) => onChange({ outcome: value }), { id: 'choose-outcome' })),
    el('label', {}, 'Along ', select(numericAxes.map((a) => [a.name, axisLabel(a.name)]), xAxis,
      (value) => onChange({ x: value }), { id: 'choose-x' })),
    slices);
}

// The parts a study has once it has results: the lookup-table links, and the correlations, asked
// for once the page is drawn (fitting a large study the first time takes seconds, and the page
// does not wait for it). A study without results has nothing to fit or tabulate (the correlations
// answer 404, the tables 409): neither is shown then.
function loadResultParts(id, { hasResults, plots, tablesHolder, redraw, stopped }) {
  if (!hasResults) return;
  replaceChildren(tablesHolder, tablesPanel(id));
  loadCorrelationSummary(id).then((summary) => {
    if (!summary || stopped()) return;
    plots.setCorrelations(new Correlations(id, summary));
    redraw();
  }).catch(() => {});
}

export async function showStudy(view, parameters, { showNotice }) {
  const state = new ViewState(parameters);
  const id = Number(state.get('study'));
  const caseTable = createCaseTable({ state, studyId: id });
  const firstCases = caseTable.fetchPage();
  firstCases.catch(() => {});
  const [study, grid] = await Promise.all([getJson(`/api/studies/${id}`), getJson(`/api/studies/${id}/grid`)]);
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
  let top = header(study, { onCancel });
  const plots = createPlots({ state });
  const tablesHolder = el('div');
  const controlsHolder = el('div');
  const drawControls = () => replaceChildren(controlsHolder, controls(state, current.grid, (changes) => {
    state.set(changes);
    drawControls();
    plots.draw(current.grid);
  }));
  const headerHolder = el('div', {}, top.node);
  replaceChildren(view, headerHolder,
    el('h2', {}, 'Axes'), axesTable(grid.axes),
    el('h2', {}, 'Outcomes'), controlsHolder, plots.node, tablesHolder,
    el('h2', {}, 'Cases'), caseTable.node);
  drawControls();
  await Promise.all([plots.draw(grid), caseTable.load(grid.axes, firstCases)]);
  loadResultParts(id, {
    hasResults: study.progress.counts.done > 0, plots, tablesHolder,
    redraw: () => plots.draw(current.grid), stopped: () => stopped,
  });

  async function refresh() {
    const [nextStudy, nextGrid] = await Promise.all([getJson(`/api/studies/${id}`), getJson(`/api/studies/${id}/grid`)]);
    if (stopped) return;
    current = { study: nextStudy, grid: nextGrid };
    top = header(nextStudy, { onCancel });
    replaceChildren(headerHolder, top.node);
    await Promise.all([plots.draw(nextGrid), caseTable.load(nextGrid.axes)]);
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
