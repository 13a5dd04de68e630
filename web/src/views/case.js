// One case: what it is, its outcome (class, cracks, re-entrained fragments), validity, energy groups
// and budget, fragments, attempts and errors, and its H5MD file to download.
import { getJson } from '../api.js';
import { el, formatNumber, formatTime, replaceChildren, table } from '../dom.js';
import { plotCurves } from '../charts.js';
import { energyGroupsSection, facts, outcomeSection, validitySection } from './case_outcome.js';


function energySection(energy) {
  if (!energy) return null;
  const shares = Object.entries(energy.dissipated_share || {});
  const bar = (share) => {
    const node = el('span', { class: 'bar' });
    node.style.width = `${Math.max(0, Math.min(1, share || 0)) * 12}em`;
    return node;
  };
  const budgets = Object.keys(energy.initial || {}).filter((key) => typeof energy.initial[key] === 'number');
  return el('section', { class: 'panel', id: 'energy' }, el('h2', {}, 'Energy budget'),
    facts([['impact kinetic energy', formatNumber(energy.impact_kinetic, 4)], ['balance drift', formatNumber(energy.balance_drift, 3)]]),
    table([{ label: 'Dissipated in', value: ([channel]) => channel },
      { label: 'Share of impact energy', value: ([, share]) => formatNumber(share, 3), numeric: true },
      { label: '', value: ([, share]) => bar(share) }], shares, { id: 'energy-shares' }),
    budgets.length > 0 && table([{ label: 'Budget term', value: (key) => key.replaceAll('_', ' ') },
      { label: 'Initial', value: (key) => formatNumber(energy.initial[key], 4), numeric: true },
      { label: 'Final', value: (key) => formatNumber((energy.final || {})[key], 4), numeric: true }], budgets));
}

function fragmentsSection(detail) {
  const chart = el('div', { class: 'chart', id: 'plot-case-fragments' });
  const section = el('section', { class: 'panel', id: 'fragments' }, el('h2', {}, `Fragments (${detail.fragments.length})`), chart,
    table([{ label: 'Rank', value: (f) => f.rank, numeric: true }, { label: 'Primaries', value: (f) => f.primaries, numeric: true },
      { label: 'Mass', value: (f) => formatNumber(f.mass, 4), numeric: true }, { label: 'On wall', value: (f) => (f.on_wall ? 'yes' : 'no') },
      { label: 'Normal velocity', value: (f) => formatNumber(f.normal_velocity, 3), numeric: true },
      { label: 'Rg', value: (f) => formatNumber(f.radius_of_gyration, 3), numeric: true }], detail.fragments, { id: 'fragments-table' }));
  const sizes = ((detail.result || {}).fragments || {}).size_distribution || [];
  return { section, draw: () => plotCurves(chart, sizes.length ? [{ label: 'fragments', points: sizes.map((s) => ({ x: s.size, y: s.count })) }] : [],
    { xLabel: 'fragment size (primaries)', yLabel: 'fragments', withBands: false, pointsOnly: true }) };
}

function attemptsSection(detail) {
  return el('section', { class: 'panel', id: 'attempts' }, el('h2', {}, 'Attempts'),
    table([{ label: 'Attempt', value: (a) => a.attempt, numeric: true }, { label: 'Job', value: (a) => a.job ?? '–' },
      { label: 'Worker', value: (a) => a.worker || '–' }, { label: 'Started', value: (a) => formatTime(a.started_at) },
      { label: 'Ended', value: (a) => formatTime(a.ended_at) }, { label: 'How it ended', value: (a) => a.outcome || 'running' },
      { label: 'Error', value: (a) => a.error || '', className: 'error' }], detail.attempt_history, { id: 'attempts-table' }));
}

export async function showCase(view, parameters) {
  const id = Number(parameters.get('case'));
  const detail = await getJson(`/api/cases/${id}`);
  const result = detail.result || {};
  const fragments = fragmentsSection(detail);
  replaceChildren(view,
    el('h1', { id: 'case-title' }, `Case ${detail.id}`),
    el('p', { class: 'description' }, (detail.document || {}).name || ''),
    facts([['status', detail.status], ['outcome', detail.outcome], ['grid point', JSON.stringify(detail.grid_point)],
      ['replicate', String(detail.replicate)], ['hash', detail.hash], ['attempts', `${detail.attempts} (${detail.failures} failed)`],
      ['worker', detail.worker], ['finished', formatTime(detail.finished_at)], ['error', detail.error]]),
    detail.data_file ? el('p', {}, el('a', { href: `/api/cases/${id}/data`, download: `case-${id}.h5`, id: 'download-h5' },
      'Download the H5MD file'), ' (start and end states; OVITO reads it)') : el('p', { class: 'note' }, 'No H5MD file: the case has no result.'),
    el('div', { class: 'grid' },
      outcomeSection(result.outcome), validitySection(result.validity), energyGroupsSection(result.dimensionless, result.si),
      energySection(result.energy), fragments.section, attemptsSection(detail)));
  fragments.draw();
  return null;
}
