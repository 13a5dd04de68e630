// The study's plots: outcome probability with 95 % bands (and fitted curves), critical speed
// against N, retained mass fraction, restitution and fragment-size distributions.
import { getJson } from '../api.js';
import { el, formatNumber, replaceChildren, select } from '../dom.js';
import { assignColors, plotCurves } from '../charts.js';
import { fittedCriticalCurves, fittedCurves } from '../correlations.js';
import {
  alongAxis, axisLabel, criticalSpeedCurves, curvesAlong, defaultXAxis, flaggedPoints, fragmentCurves, meanOf, probabilityOf,
  sliceAxes, valueKey,
} from '../series.js';
import { createFlags } from './study_flags.js';

function panel(id, title, note) {
  const chart = el('div', { class: 'chart', id: `plot-${id}` });
  const noteNode = el('p', { class: 'note' }, note);
  const extra = el('div', { class: 'controls' });
  const node = el('section', { class: 'panel', id: `panel-${id}` }, el('h2', {}, title), extra, chart, noteNode);
  return { node, chart, noteNode, extra };
}

function currentSlice(state, axes, xAxis) {
  return Object.fromEntries(sliceAxes(axes, xAxis).map((axis) => [axis.name, state.get(`s.${axis.name}`, valueKey(axis.values[0]))]));
}

function axisQuery(values) {
  const search = new URLSearchParams();
  for (const [axis, key] of Object.entries(values)) search.append(`axis.${axis}`, key);
  return search.toString();
}

function correlationsTable(correlations) {
  if (!correlations) return null;
  const rows = correlations.map((item) => el('tr', {},
    el('td', {}, item.name || ''), el('td', {}, item.outcome || ''), el('td', {}, JSON.stringify(item.group || {})),
    el('td', {}, Object.entries(item.critical_speeds || {}).map(([level, estimate]) =>
      `${level} ${formatNumber(estimate && estimate.value)} [${(estimate && estimate.ci95 || []).map((v) => formatNumber(v)).join(', ')}]`).join('; '))));
  return el('section', { class: 'panel', id: 'panel-correlations' }, el('h2', {}, 'Correlations'),
    el('table', {}, el('thead', {}, el('tr', {}, ['Name', 'Outcome', 'Group', 'Critical speeds (95 %)'].map((h) => el('th', {}, h)))),
      el('tbody', {}, rows)));
}

export function createPlots({ state, correlations }) {
  const probability = panel('probability', 'Outcome probability', 'Bands: 95 % Wilson intervals of each grid point. Red ' +
    'rings: grid points with results outside the small-strain range. Along the energy per contact, each point is a grid ' +
    'point at its mean E_kin / (N_c E_break).');
  const critical = panel('critical', 'Critical speed against N',
    'Points: where the measured probability crosses 0.5 (interpolated in log speed between grid points).');
  const retained = panel('retained', 'Retained mass fraction', 'Mean of the results, band: 95 % Student interval.');
  const restitution = panel('restitution', 'Restitution (largest fragment, normal)', 'Mean of the results, band: 95 % Student interval.');
  const damage = panel('damage', 'Damage ratio', 'Initial contacts broken by the end over the initial contacts: mean of the ' +
    'results, band: 95 % Student interval.');
  const flags = createFlags();
  const fragments = panel('fragments', 'Fragment-size distribution', 'Fragments of each size per result, one series per grid value.');
  const node = el('div', {}, el('div', { class: 'grid' }, probability.node, critical.node, retained.node, damage.node, restitution.node,
    fragments.node, flags.node),
    correlationsTable(correlations));
  let fragmentRequest = 0;

  async function drawFragments(studyId, curves, xAxis, slice) {
    const groups = curves.map((curve) => [curve.key, curve.label]);
    const chosen = state.get('fs', groups.length ? groups[0][0] : '');
    const group = (curves.find((curve) => curve.key === chosen) || curves[0] || { groupValues: {} }).groupValues;
    replaceChildren(fragments.extra, groups.length > 1 && el('label', {}, 'Series ',
      select(groups, chosen, (value) => { state.set({ fs: value }); drawFragments(studyId, curves, xAxis, slice); },
        { id: 'choose-fragment-group' })));
    const filter = { ...slice, ...Object.fromEntries(Object.entries(group).map(([axis, value]) => [axis, valueKey(value)])) };
    const request = ++fragmentRequest;
    const response = await getJson(`/api/studies/${studyId}/fragment-sizes?${axisQuery(filter)}`);
    if (request !== fragmentRequest) return;
    plotCurves(fragments.chart, fragmentCurves(response, xAxis), {
      xLabel: 'fragment size (primaries)', yLabel: 'fragments per result', withBands: false, yLog: true });
  }

  function draw(grid) {
    const xAxis = state.get('x', defaultXAxis(grid.axes));
    const outcome = state.get('outcome', 'break-up');
    const slice = currentSlice(state, grid.axes, xAxis);
    const along = { axes: grid.axes, xAxis, slice };
    const xLabel = axisLabel(xAxis);
    const measured = curvesAlong(grid.grid_points, { ...along, yOf: probabilityOf(outcome) });
    assignColors(measured);
    const flagged = flaggedPoints(measured, 'small_strain_exceeded', 'outside the small-strain range');
    plotCurves(probability.chart, [...measured, ...fittedCurves(correlations, outcome, measured),
      ...(flagged.points.length ? [flagged] : [])], { xLabel, yLabel: `P(${outcome})`, yRange: [0, 1] });

    const hasN = grid.axes.some((axis) => axis.name === 'primaries' && axis.values.length > 1) && alongAxis(xAxis) !== 'primaries';
    critical.node.hidden = !hasN;
    if (hasN) plotCurves(critical.chart, [...criticalSpeedCurves(measured), ...fittedCriticalCurves(correlations, outcome)],
      { xLabel: 'N (primaries)', yLabel: `critical ${xLabel} for ${outcome}`, pointsOnly: true, yLog: true });

    plotCurves(retained.chart, curvesAlong(grid.grid_points, { ...along, yOf: meanOf('retained_mass_fraction') }),
      { xLabel, yLabel: 'retained mass fraction', yRange: [0, 1] });
    plotCurves(damage.chart, curvesAlong(grid.grid_points, { ...along, yOf: meanOf('damage_ratio') }),
      { xLabel, yLabel: 'damage ratio', yRange: [0, 1] });
    const shownAxes = grid.axes.filter((axis) => axis.values.length > 1 && !(axis.name in slice)).map((axis) => axis.name);
    flags.draw(grid, { slice, shownAxes });
    plotCurves(restitution.chart, curvesAlong(grid.grid_points, { ...along, yOf: meanOf('restitution') }),
      { xLabel, yLabel: 'normal restitution' });
    return drawFragments(grid.study, measured, xAxis, slice).catch((error) => {
      replaceChildren(fragments.chart, el('p', { class: 'note' }, error.message));
    });
  }
  return { node, draw };
}
