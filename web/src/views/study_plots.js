// The study's plots: outcome probability with 95 % bands (and fitted curves), critical speed
// against N (measured and fitted), retained mass fraction, damage ratio, restitution and
// fragment-size distributions; the flagged results and the correlations panel.
import { getJson } from '../api.js';
import { el, replaceChildren, select } from '../dom.js';
import { assignColors, plotCurves } from '../charts.js';
import {
  alongAxis, axisLabel, curvesAlong, defaultXAxis, flaggedPoints, fragmentCurves, meanOf, probabilityOf,
  sliceAxes, valueKey,
} from '../series.js';
import { createFlags } from './study_flags.js';
import { createCorrelationsPanel } from './study_correlations.js';

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

export function createPlots({ state }) {
  const probability = panel('probability', 'Outcome probability', 'Bands: 95 % Wilson intervals of each grid point. Red ' +
    'rings: grid points with results outside the small-strain range. Along the energy per contact, each point is a grid ' +
    'point at its mean E_kin / (N_c E_break).');
  const critical = panel('critical', 'Critical speed against N',
    'Points: where the measured probability crosses 0.5 (interpolated in log speed between grid points). Lines, where ' +
    'the correlations service has fits: the fitted v50 with its 95 % interval (band), v10 and v90 dashed.');
  const retained = panel('retained', 'Retained mass fraction', 'Mean of the results, band: 95 % Student interval.');
  const restitution = panel('restitution', 'Restitution (largest fragment, normal)', 'Mean of the results, band: 95 % Student interval.');
  const damage = panel('damage', 'Damage ratio', 'Initial contacts broken by the end over the initial contacts: mean of the ' +
    'results, band: 95 % Student interval.');
  const flags = createFlags();
  const correlationsPanel = createCorrelationsPanel();
  const fragments = panel('fragments', 'Fragment-size distribution', 'Fragments of each size per result, one series per grid value.');
  const node = el('div', {}, el('div', { class: 'grid' }, probability.node, critical.node, retained.node, damage.node, restitution.node,
    fragments.node, flags.node), correlationsPanel.node);
  let fragmentRequest = 0;
  let correlations = null;
  let drawing = 0;

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

  // The probability and critical-value plots: the measured curves at once, then with the fits where
  // the correlations service has them (each chart's dataset.fitted counts the fitted curves drawn).
  async function drawOutcomes(grid, view) {
    const { outcome, xAxis, slice, xLabel } = view;
    const measured = curvesAlong(grid.grid_points, { axes: grid.axes, xAxis, slice, yOf: probabilityOf(outcome) });
    assignColors(measured);
    const flagged = flaggedPoints(measured, 'small_strain_exceeded', 'outside the small-strain range');
    const markers = flagged.points.length ? [flagged] : [];
    const hasN = grid.axes.some((axis) => axis.name === 'primaries' && axis.values.length > 1) && alongAxis(xAxis) !== 'primaries';
    // The measured crossings come from the service (observed_crossings), like the fitted ones.
    const measuredCritical = hasN && correlations ? correlations.observedCurves(outcome, xAxis, slice) : [];
    const drawBoth = (fitted, fittedCritical) => {
      plotCurves(probability.chart, [...measured, ...fitted, ...markers], { xLabel, yLabel: `P(${outcome})`, yRange: [0, 1] });
      probability.chart.dataset.fitted = fitted.length;
      critical.node.hidden = !hasN;
      if (!hasN) return;
      plotCurves(critical.chart, [...measuredCritical, ...fittedCritical],
        { xLabel: 'N (primaries)', yLabel: `critical ${xLabel} for ${outcome}`, yLog: true });
      critical.chart.dataset.fitted = fittedCritical.length;
    };
    drawBoth([], []);
    correlationsPanel.draw(correlations, view);
    if (!correlations) return measured;
    const mine = ++drawing;
    const fitted = await correlations.fittedCurves(measured, view);
    if (mine === drawing) drawBoth(fitted, hasN ? correlations.criticalCurves(outcome, xAxis, slice) : []);
    return measured;
  }

  function draw(grid) {
    const xAxis = state.get('x', defaultXAxis(grid.axes));
    const slice = currentSlice(state, grid.axes, xAxis);
    const view = { outcome: state.get('outcome', 'break-up'), xAxis, slice, xLabel: axisLabel(xAxis) };
    const along = { axes: grid.axes, xAxis, slice };
    const outcomes = drawOutcomes(grid, view).catch((error) => {
      replaceChildren(probability.noteNode, `The fits could not be drawn: ${error.message}`);
    });
    plotCurves(retained.chart, curvesAlong(grid.grid_points, { ...along, yOf: meanOf('retained_mass_fraction') }),
      { xLabel: view.xLabel, yLabel: 'retained mass fraction', yRange: [0, 1] });
    plotCurves(damage.chart, curvesAlong(grid.grid_points, { ...along, yOf: meanOf('damage_ratio') }),
      { xLabel: view.xLabel, yLabel: 'damage ratio', yRange: [0, 1] });
    const shownAxes = grid.axes.filter((axis) => axis.values.length > 1 && !(axis.name in slice)).map((axis) => axis.name);
    flags.draw(grid, { slice, shownAxes });
    plotCurves(restitution.chart, curvesAlong(grid.grid_points, { ...along, yOf: meanOf('restitution') }),
      { xLabel: view.xLabel, yLabel: 'normal restitution' });
    const seriesCurves = curvesAlong(grid.grid_points, { ...along, yOf: probabilityOf(view.outcome) });
    const sizes = drawFragments(grid.study, seriesCurves, xAxis, slice).catch((error) => {
      replaceChildren(fragments.chart, el('p', { class: 'note' }, error.message));
    });
    return Promise.all([outcomes, sizes]);
  }

  // The correlations service's fits (correlations.js Correlations), once they have arrived.
  function setCorrelations(value) {
    correlations = value;
  }
  return { node, draw, setCorrelations };
}
