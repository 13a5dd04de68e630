// One case: what it is, its outcome (class, cracks, re-entrained fragments), validity, energy groups
// and budget, fragments, attempts and errors, and its H5MD file to download. Every dimensional
// value is in the case's units (SI for a physical case; units.js caseUnits).
import { getJson } from '../api.js';
import { el, formatNumber, formatTime, replaceChildren, table } from '../dom.js';
import { plotCurves } from '../charts.js';
import { AxisNames } from '../axis_names.js';
import { caseUnits } from '../units.js';
import { energyGroupsSection, facts, outcomeSection, validitySection } from './case_outcome.js';

// A numeric column of a quantity of `kind` (speed, mass, ...) converted to the case's units.
const quantityColumn = (units, label, kind, field, digits) => ({
  label: units.label(label, kind), value: (row) => formatNumber(units.value(row[field], kind), digits),
    numeric: true });

function shareBar(share) {
  const node = el('span', { class: 'bar' });
  node.style.width = `${Math.max(0, Math.min(1, share || 0)) * 12}em`;
  return node;
}

function energySection(energy, units) {
  if (!energy) return null;
  const shares = Object.entries(energy.dissipated_share || {});
  const initial = energy.initial || {};
  const budgets = Object.keys(initial).filter((key) => typeof initial[key] === 'number');
  const terms = budgets.map((key) => ({ term: key.replaceAll('_', ' '), initial: initial[key],
    final: (energy.final || {})[key] }));
  return el('section', { class: 'panel', id: 'energy' }, el('h2', {}, 'Energy budget'),
    facts([[units.label('impact kinetic energy', 'energy'), formatNumber(units.value(energy.impact_kinetic, 'energy'),
      4)],
      ['balance drift (share of the energy turnover)', formatNumber(energy.balance_drift, 3)]]),
    table([{ label: 'Dissipated in', value: ([channel]) => channel },
      { label: 'Share of impact energy', value: ([, share]) => formatNumber(share, 3), numeric: true },
      { label: '', value: ([, share]) => shareBar(share) }], shares, { id: 'energy-shares' }),
    terms.length > 0 && table([{ label: 'Budget term', value: (row) => row.term },
      quantityColumn(units, 'Initial', 'energy', 'initial', 4), quantityColumn(units, 'Final', 'energy', 'final', 4)],
        terms));
}

function fragmentsSection(detail, units) {
  const chart = el('div', { class: 'chart', id: 'plot-case-fragments' });
  const columns = [{ label: 'Rank', value: (f) => f.rank, numeric: true },
    { label: 'Primaries', value: (f) => f.primaries, numeric: true }, quantityColumn(units, 'Mass', 'mass', 'mass', 4),
    { label: 'On wall', value: (f) => (f.on_wall ? 'yes' : 'no') },
    quantityColumn(units, 'Normal velocity', 'speed', 'normal_velocity', 3),
    quantityColumn(units, 'Rg', 'length', 'radius_of_gyration', 3)];
  const section = el('section', { class: 'panel', id: 'fragments' }, el('h2', {},
    `Fragments (${detail.fragments.length})`),
    chart, table(columns, detail.fragments, { id: 'fragments-table' }));
  const sizes = ((detail.result || {}).fragments || {}).size_distribution || [];
  const curves = sizes.length ? [{ label: 'fragments', style: 'points', points: sizes.map((s) => ({ x: s.size,
    y: s.count })) }] : [];
  return { section, draw: () => plotCurves(chart, curves, { xLabel: 'fragment size (primaries)',
    yLabel: 'fragments' }) };
}

function attemptsSection(detail) {
  return el('section', { class: 'panel', id: 'attempts' }, el('h2', {}, 'Attempts'),
    table([{ label: 'Attempt', value: (a) => a.attempt, numeric: true }, { label: 'Job', value: (a) => a.job ?? '–' },
      { label: 'Worker', value: (a) => a.worker || '–' }, { label: 'Started', value: (a) => formatTime(a.started_at) },
      { label: 'Ended', value: (a) => formatTime(a.ended_at) },
      { label: 'How it ended', value: (a) => a.outcome || 'running' },
      { label: 'Error', value: (a) => a.error || '', className: 'error' }],
    detail.attempt_history, { id: 'attempts-table' }));
}

// The grid point's values in words, each axis with its unit: the study's inputs, in the case's
// unit system, named as the service describes them (GET /api/cases/ID: axes).
const valueText = (value) => (typeof value === 'number' ? formatNumber(value, 6) : JSON.stringify(value));
const gridPointText = (gridPoint, names) => Object.entries(gridPoint || {})
  .map(([axis, value]) => `${names.label(axis)} = ${valueText(value)}`).join(', ');

const kUnitSystems = { physical: 'SI (a physical case)', reduced: 'reduced: d, m, τ = √(m/k_n), energy k_n d²' };

function download(detail) {
  if (!detail.data_file) return el('p', { class: 'note' }, 'No H5MD file: the case has no result.');
  return el('p', {}, el('a', { href: `/api/cases/${detail.id}/data`, download: `case-${detail.id}.h5`,
    id: 'download-h5' },
    'Download the H5MD file'), ' (start and end states; OVITO reads it)');
}

export async function showCase(view, parameters) {
  const id = Number(parameters.get('case'));
  const detail = await getJson(`/api/cases/${id}`);
  const result = detail.result || {};
  const units = caseUnits(detail);
  const fragments = fragmentsSection(detail, units);
  replaceChildren(view,
    el('h1', { id: 'case-title' }, `Case ${detail.id}`),
    el('p', { class: 'description' }, (detail.document || {}).name || ''),
    facts([['status', detail.status], ['outcome', detail.outcome],
      ['grid point', gridPointText(detail.grid_point, new AxisNames(detail.axes))],
      ['units', kUnitSystems[detail.units.system]],
      ['replicate', String(detail.replicate)], ['hash', detail.hash],
      ['attempts', `${detail.attempts} (${detail.failures} failed)`],
      ['worker', detail.worker], ['finished', formatTime(detail.finished_at)], ['error', detail.error]]),
    download(detail),
    el('div', { class: 'grid' },
      outcomeSection(result.outcome, units), validitySection(result.validity), energyGroupsSection(result, units),
      energySection(result.energy, units), fragments.section, attemptsSection(detail)));
  fragments.draw();
  return null;
}
