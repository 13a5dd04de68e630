// The study's plots: outcome probability (measured with 95 % whiskers, fitted curves with their
// bands), critical speed against N (measured and fitted), retained mass fraction, damage ratio,
// restitution and fragment-size distributions; the flagged results and the correlations panel.
// Each chart is drawn in a task of its own, so that the page keeps answering while a large study
// draws; a newer draw stops an older one at its next chart.
import { getJson } from '../api.js';
import { el, replaceChildren, select } from '../dom.js';
import { colourGroups, plotCurves } from '../charts.js';
import {
  alongAxis, conditionKey, curvesAlong, defaultXAxis, flaggedPoints, fragmentCurves,
  meanOf, probabilityOf, sliceAxes, valueKey,
} from '../series.js';
import { withUnit } from '../units.js';
import { levelName } from '../correlations.js';
import { createFlags } from './study_flags.js';
import { createCorrelationsPanel } from './study_correlations.js';

const kBounded = [0, 1];

// Lets the browser paint and handle input before the next chart.
const nextTask = () => (globalThis.scheduler?.yield ? globalThis.scheduler.yield()
  : new Promise((resolve) => setTimeout(resolve, 0)));

function panel(id, title, note) {
  const chart = el('div', { class: 'chart', id: `plot-${id}` });
  const noteNode = el('p', { class: 'note' }, note);
  const extra = el('div', { class: 'controls' });
  const heading = el('h2', {}, title);
  const node = el('section', { class: 'panel', id: `panel-${id}` }, heading, extra, chart, noteNode);
  return { node, chart, noteNode, extra, heading };
}

function currentSlice(state, axes, xAxis) {
  return Object.fromEntries(sliceAxes(axes, xAxis)
    .map((axis) => [axis.name, state.get(`s.${axis.name}`, valueKey(axis.values[0]))]));
}

function axisQuery(values) {
  const search = new URLSearchParams();
  for (const [axis, key] of Object.entries(values)) search.append(`axis.${axis}`, key);
  return search.toString();
}

const kProbabilityNote = 'Points: the measured probability of each grid point, whiskers its 95 % Wilson interval. ' +
  'Dashed, where the correlations service has fits: the fitted logistic curve of each group with its 95 % band. ' +
  'Red rings: grid points with results outside the small-strain range. Along the energy per contact, each point ' +
  'is a grid point at its mean E_kin / (N_c E_break). Click a legend entry to hide or show its series.';
const kCriticalNote = 'Points: where the measured probability crosses 0.5 (interpolated in log speed between grid ' +
  'points). Lines, where the correlations service has fits: the fitted v50 (solid) with its 95 % interval (band), ' +
  'v10 (dashed) and v90 (dotted); along the energy per contact E10, E50 and E90. The axis spans the estimates: an ' +
  'interval reaching beyond is cut at the edge (its numbers are in the correlations table).';
const kStudent = 'Mean of the results, whiskers: 95 % Student interval';
const kNoBounces = 'Nothing to plot: no case here bounced (the restitution is that of the bounces).';

function createPanels() {
  return {
    probability: panel('probability', 'Outcome probability', kProbabilityNote),
    critical: panel('critical', 'Critical speed against N', kCriticalNote),
    retained: panel('retained', 'Retained mass fraction', `${kStudent} (within 0 and 1).`),
    damage: panel('damage', 'Damage ratio', 'Initial contacts broken by the end over the initial contacts. ' +
      `${kStudent} (within 0 and 1).`),
    restitution: panel('restitution', 'Restitution (largest fragment, normal)',
      'Mean over the bounces only (a stick or a break-up has none), whiskers: 95 % Student interval.'),
    fragments: panel('fragments', 'Fragment-size distribution',
      'Fragments of each size per result, one series per grid value.'),
  };
}

// Measured curves of the series axes' groups (series.js curvesAlong), coloured by group, each the
// measured member of its group in the legend (chart_legend.js).
function measuredGroups(curves, styleLabel) {
  return colourGroups(curves)
    .map((curve) => Object.assign(curve, { group: curve.key, groupLabel: curve.label, styleLabel }));
}

// The measured crossings as the service computes them (correlations.js observedCurves).
function measuredCritical(observed, xAxis) {
  return observed.map((curve) => ({
    ...curve, style: 'points', group: conditionKey(curve.groupValues), groupLabel: curve.label,
    styleLabel: `measured ${levelName(0.5, xAxis)}`,
    label: `measured ${levelName(0.5, xAxis)}${curve.label === 'all' ? '' : `, ${curve.label}`}` }));
}

// The critical value along x against N, in the unit of the x axis (the service's description).
function drawCritical(critical, view, observed, fitted) {
  const { names, xAxis } = view;
  const hasN = view.axes.some((axis) => axis.name === 'primaries' && axis.values.length > 1) &&
    alongAxis(xAxis) !== 'primaries';
  critical.node.hidden = !hasN;
  if (!hasN) return;
  const speed = xAxis === 'impact_speed';
  critical.heading.textContent = `Critical ${speed ? 'speed' : names.label(xAxis)} of ${view.outcome} against N`;
  const points = measuredCritical(observed, xAxis);
  colourGroups([...points, ...fitted]);
  plotCurves(critical.chart, [...points, ...fitted], { xLabel: names.label('primaries'),
    xLog: names.logScale('primaries'),
    yLabel: withUnit(`critical ${speed ? 'speed' : names.symbol(xAxis)}`, names.unit(xAxis)),
    yLog: true, fitIntervals: false });
  critical.chart.dataset.fitted = fitted.length;
}

// The fragment-size plot of one series (chosen in its own select, kept in the URL as `fs`).
function createFragmentsPlot(state, fragments) {
  let request = 0;
  async function draw(studyId, curves, view) {
    const groups = curves.map((curve) => [curve.key, curve.label]);
    const chosen = state.get('fs', groups.length ? groups[0][0] : '');
    const group = (curves.find((curve) => curve.key === chosen) || curves[0] || { groupValues: {} }).groupValues;
    const choose = (value) => {
      state.set({ fs: value });
      draw(studyId, curves, view);
    };
    replaceChildren(fragments.extra, groups.length > 1 &&
      el('label', {}, 'Series ', select(groups, chosen, choose, { id: 'choose-fragment-group' })));
    const groupKeys = Object.fromEntries(Object.entries(group).map(([axis, value]) => [axis, valueKey(value)]));
    const mine = ++request;
    const query = axisQuery({ ...view.slice, ...groupKeys });
    const response = await getJson(`/api/studies/${studyId}/fragment-sizes?${query}`);
    if (mine !== request) return;
    plotCurves(fragments.chart, fragmentCurves(response, view.xAxis, view.names), {
      xLabel: 'fragment size (primaries)', yLabel: 'fragments per result', yLog: true });
  }
  return draw;
}

// The probability and critical-value plots and the correlations panel: the measured curves at
// once, then with the fits where the correlations service has them (each chart's dataset.fitted
// counts the fitted curves drawn). A newer call stops an older one.
function createOutcomePlots({ probability, critical }, correlationsPanel) {
  let drawing = 0;
  return async (grid, view, correlations) => {
    const mine = ++drawing;
    await nextTask();
    if (mine !== drawing) return;
    const along = { axes: grid.axes, xAxis: view.xAxis, slice: view.slice, names: view.names };
    const measured = measuredGroups(curvesAlong(grid.grid_points, { ...along, yOf: probabilityOf(view.outcome) }),
      'measured, whiskers: 95 % interval');
    const flagged = flaggedPoints(measured, 'small_strain_exceeded', 'outside the small-strain range');
    const markers = flagged.points.length ? [flagged] : [];
    const drawBoth = async (fitted, fittedCritical, observed) => {
      plotCurves(probability.chart, [...measured, ...fitted, ...markers],
        { xLabel: view.xLabel, xLog: view.xLog, yLabel: `P(${view.outcome})`, bounds: kBounded });
      probability.chart.dataset.fitted = fitted.length;
      probability.chart.dataset.outcome = view.outcome;
      await nextTask();
      if (mine === drawing) drawCritical(critical, view, observed, fittedCritical);
    };
    await drawBoth([], [], []);
    if (mine !== drawing) return;
    correlationsPanel.draw(correlations, view);
    if (!correlations) return;
    const fitted = await correlations.fittedCurves(measured, view);
    if (mine === drawing)
      await drawBoth(fitted, correlations.criticalCurves(view.outcome, view.xAxis, view.slice, view.names),
        correlations.observedCurves(view.outcome, view.xAxis, view.slice, view.names));
  };
}

export function createPlots({ state }) {
  const panels = createPanels();
  const flags = createFlags();
  const correlationsPanel = createCorrelationsPanel();
  const { probability, critical, retained, damage, restitution, fragments } = panels;
  const node = el('div', {}, el('div', { class: 'grid' }, probability.node, critical.node, retained.node, damage.node,
    restitution.node, fragments.node, flags.node), correlationsPanel.node);
  const drawFragments = createFragmentsPlot(state, fragments);
  const drawOutcomePlots = createOutcomePlots(panels, correlationsPanel);
  let correlations = null;
  let drawing = 0;

  // The plots that do not depend on the outcome, one task each; stops when a newer draw began.
  async function drawQuantities(grid, view, mine) {
    const along = { axes: grid.axes, xAxis: view.xAxis, slice: view.slice, names: view.names };
    const charts = [
      [retained.chart, 'retained_mass_fraction', 'retained mass fraction', kBounded, undefined],
      [damage.chart, 'damage_ratio', 'damage ratio', kBounded, undefined],
      [restitution.chart, 'restitution', 'normal restitution', null, kNoBounces],
    ];
    for (const [chart, quantity, yLabel, bounds, empty] of charts) {
      await nextTask();
      if (mine !== drawing) return;
      const curves = measuredGroups(curvesAlong(grid.grid_points, { ...along, yOf: meanOf(quantity) }),
        'mean, whiskers: 95 % interval');
      plotCurves(chart, curves, { xLabel: view.xLabel, xLog: view.xLog, yLabel, bounds, empty });
    }
    await nextTask();
    if (mine !== drawing) return;
    const shownAxes = grid.axes.filter((axis) => axis.values.length > 1 && !(axis.name in view.slice))
      .map((axis) => axis.name);
    flags.draw(grid, { slice: view.slice, shownAxes, names: view.names });
    const seriesCurves = curvesAlong(grid.grid_points, { ...along, yOf: probabilityOf(view.outcome) });
    await drawFragments(grid.study, seriesCurves, view).catch((error) => {
      replaceChildren(fragments.chart, el('p', { class: 'note' }, error.message));
    });
  }

  // `names`: the study's axes as the service describes them (axis_names.js AxisNames).
  function currentView(grid, names) {
    const xAxis = state.get('x', defaultXAxis(grid.axes));
    return { outcome: state.get('outcome', 'break-up'), xAxis, slice: currentSlice(state, grid.axes, xAxis), names,
      xLabel: names.label(xAxis), xLog: names.logScale(xAxis), axes: grid.axes };
  }

  const outcomesOf = (grid, view) => drawOutcomePlots(grid, view, correlations).catch((error) => {
    replaceChildren(probability.noteNode, `The fits could not be drawn: ${error.message}`);
  });

  return {
    node,
    // Every plot, for the grid statistics `grid` of a study whose axes `names` describes.
    draw: (grid, names) => {
      const view = currentView(grid, names);
      return Promise.all([outcomesOf(grid, view), drawQuantities(grid, view, ++drawing)]);
    },
    // Only what depends on the outcome (another outcome chosen, or the fits arrived).
    drawOutcome: (grid, names) => outcomesOf(grid, currentView(grid, names)),
    // The correlations service's fits (correlations.js Correlations), once they have arrived.
    setCorrelations: (value) => {
      correlations = value;
    },
  };
}
