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
  meanOf, probabilityOf, resultsIn, sliceAxes, valueKey,
} from '../series.js';
import { withUnit } from '../units.js';
import { kDerivedX } from '../axis_names.js';
import { doseOf, levelName } from '../correlations.js';
import { curveBins, kSearchBins, pooledFragmentCurves, pooledProbabilityCurves } from '../search_bins.js';
import { loadSearch, searchCrossings } from '../search_estimates.js';
import { createFlags, fourDigits } from './study_flags.js';
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

function currentSlice(state, axes, xAxis, names) {
  return Object.fromEntries(sliceAxes(axes, xAxis, names)
    .map((axis) => [axis.name, state.get(`s.${axis.name}`, valueKey(axis.values[0]))]));
}

function axisQuery(values) {
  const search = new URLSearchParams();
  for (const [axis, key] of Object.entries(values)) search.append(`axis.${axis}`, key);
  return search.toString();
}

const kProbabilityNote = 'Points: the measured probability of each grid point, the share of its determined results ' +
  '(undetermined cases, which hit their time limit, are left out, as the fits leave them out; the outcome ' +
  '"undetermined" is a share of all results), whiskers its 95 % Wilson interval. ' +
  'Dashed, where the correlations service has fits: the fitted logistic curve of each group with its 95 % band. ' +
  'Red rings: grid points with results outside the small-strain range. Along the energy per contact, each point ' +
  'is a grid point at its mean E_kin / (N_c E_break). Click a legend entry to hide or show its series.';
const kCriticalNote = 'Points: where the measured probability crosses 0.5 (interpolated in log speed between grid ' +
  'points). Lines, where the correlations service has fits: the fitted v50 (solid) with its 95 % interval (band), ' +
  'v10 (dashed) and v90 (dotted); along the energy per contact E10, E50 and E90. The axis spans the estimates: an ' +
  'interval reaching beyond is cut at the edge (its numbers are in the correlations table).';
const kSearchedNote = (symbol) => `Along the searched ${symbol} (the adaptive search placed one or a few cases ` +
  `at each value): points, the results pooled into at most ${kSearchBins} bins of about equal numbers of results ` +
  `per condition, at their results' mean ${symbol}: the share of the bin's determined results (undetermined ` +
  'cases, which hit their time limit, are left out as the fit and the search leave them out; the outcome ' +
  '"undetermined" is a share of all results), whiskers the 95 % Wilson interval of the pooled counts (no ' +
  'line). Dashed: ' +
  'the fitted logistic curve of each group with its 95 % band. White rings: the search\'s own estimate ' +
  '(docs/ADAPTIVE.md), bar: its 95 % interval. Red rings: bins with results outside the small-strain range. ' +
  'Click a legend entry to hide or show its series.';
const kFragmentsNote = 'Fragments of each size per result, one series per grid value.';
const kSearchedFragmentsNote = 'Fragments of each size per result, one series per bin of the searched axis (the ' +
  'bins of the probability plot).';
const kStudent = 'Mean of the determined results (an undetermined one, whose state is not final, is left out), ' +
  'whiskers: 95 % Student interval';
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
    fragments: panel('fragments', 'Fragment-size distribution', kFragmentsNote),
  };
}

// Measured curves of the series axes' groups (series.js curvesAlong), coloured by group (shaded by
// N), each the measured member of its group in the legend (chart_legend.js).
function measuredGroups(curves, styleLabel, names) {
  return colourGroups(curves, names.withRole('size'))
    .map((curve) => Object.assign(curve, { group: curve.key, groupLabel: curve.label, styleLabel }));
}

// The measured crossings as the service computes them (correlations.js observedCurves), named by the
// fits' dose (v50, E50).
function measuredCritical(observed, dose) {
  return observed.map((curve) => ({
    ...curve, style: 'points', group: conditionKey(curve.groupValues), groupLabel: curve.label,
    styleLabel: `measured ${levelName(0.5, dose)}`,
    label: `measured ${levelName(0.5, dose)}${curve.label === 'all' ? '' : `, ${curve.label}`}` }));
}

// The critical value along x against N, in the unit of the x axis (the service's description).
function drawCritical(critical, view, observed, fitted) {
  const { names, xAxis } = view;
  const size = names.withRole('size');
  const hasN = view.axes.some((axis) => axis.name === size && axis.values.length > 1) &&
    alongAxis(xAxis, names) !== size;
  critical.node.hidden = !hasN;
  if (!hasN) return;
  const speed = names.role(xAxis) === 'speed';
  critical.heading.textContent = `Critical ${speed ? 'speed' : names.label(xAxis)} of ${view.outcome} against N`;
  const points = measuredCritical(observed, doseOf(xAxis, names));
  colourGroups([...points, ...fitted], size);
  plotCurves(critical.chart, [...points, ...fitted], { xLabel: names.label(size), xLog: names.logScale(size),
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
    const along = alongAxis(view.xAxis, view.names);
    const searched = view.names.searched(along);
    const curve = curves.find((each) => each.groupValues === group);
    // Ranges written as the flagged-results table writes them.
    const series = searched && curve
      ? pooledFragmentCurves(response, curveBins(curve, along), { along, names: view.names, format: fourDigits })
      : fragmentCurves(response, view.xAxis, view.names);
    fragments.noteNode.textContent = searched ? kSearchedFragmentsNote : kFragmentsNote;
    plotCurves(fragments.chart, series, {
      xLabel: 'fragment size (primaries)', yLabel: 'fragments per result', yLog: true });
  }
  return draw;
}

// The measured probability curves: one point per grid point joined by a line, or along a searched
// axis the results pooled into bins (search_bins.js), points without a line.
function probabilityCurves(grid, view, searched) {
  const along = { axes: grid.axes, xAxis: view.xAxis, slice: view.slice, names: view.names };
  if (!searched) {
    const curves = curvesAlong(grid.grid_points, { ...along, yOf: probabilityOf(view.outcome) });
    return measuredGroups(curves, 'measured, whiskers: 95 % interval', view.names);
  }
  const pooled = pooledProbabilityCurves(curvesAlong(grid.grid_points, { ...along, yOf: resultsIn }),
    { outcome: view.outcome, along: alongAxis(view.xAxis, view.names), xLog: view.xLog });
  return measuredGroups(pooled, 'results pooled in bins, whiskers: 95 % interval', view.names);
}

// The search's estimates above the probability plot, one line per condition.
function searchList(crossings) {
  return crossings.length === 0 ? null : el('ul', { class: 'search-estimates', id: 'search-estimates' },
    crossings.map((curve) => el('li', {}, `${curve.label} (${curve.state}, ${curve.cases} cases)`)));
}

// The probability and critical-value plots and the correlations panel: the measured curves at
// once, then with the fits where the correlations service has them (each chart's dataset.fitted
// counts the fitted curves drawn). A newer call stops an older one.
// Along a searched axis, the search's own estimates are drawn and listed with them.
function createOutcomePlots({ probability, critical }, correlationsPanel) {
  let drawing = 0;
  let searchOf = { grid: null, answer: null };
  // The search's state, asked once per grid statistics (they change as its results arrive).
  const search = (grid) => {
    if (searchOf.grid !== grid) searchOf = { grid, answer: loadSearch(grid.study) };
    return searchOf.answer;
  };
  return async (grid, view, correlations) => {
    const mine = ++drawing;
    await nextTask();
    if (mine !== drawing) return;
    const along = alongAxis(view.xAxis, view.names);
    const searched = view.names.searched(along);
    const measured = probabilityCurves(grid, view, searched);
    const crossings = searched && !kDerivedX[view.xAxis]
      ? searchCrossings(await search(grid), measured, { outcome: view.outcome, along, names: view.names }) : [];
    if (mine !== drawing) return;
    probability.noteNode.textContent = searched ? kSearchedNote(view.names.symbol(along)) : kProbabilityNote;
    replaceChildren(probability.extra, searchList(crossings));
    const flagged = flaggedPoints(measured, 'small_strain_exceeded', 'outside the small-strain range');
    const markers = flagged.points.length ? [flagged] : [];
    const drawBoth = async (fitted, fittedCritical, observed) => {
      plotCurves(probability.chart, [...measured, ...fitted, ...crossings, ...markers], { xLabel: view.xLabel,
        xLog: view.xLog, yLabel: `P(${view.outcome})`, bounds: kBounded, dataTicks: !searched });
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
    // Along a searched axis, each grid point's mean as a point without a line (most hold one result).
    const searchedAxis = alongAxis(view.xAxis, view.names);
    const style = view.names.searched(searchedAxis) ? 'points' : 'measured';
    for (const [chart, quantity, yLabel, bounds, empty] of charts) {
      await nextTask();
      if (mine !== drawing) return;
      const curves = measuredGroups(curvesAlong(grid.grid_points, { ...along, yOf: meanOf(quantity) })
        .map((curve) => ({ ...curve, style })), 'mean, whiskers: 95 % interval', view.names);
      plotCurves(chart, curves, { xLabel: view.xLabel, xLog: view.xLog, yLabel, bounds, empty });
    }
    await nextTask();
    if (mine !== drawing) return;
    const shownAxes = grid.axes.filter((axis) => axis.values.length > 1 && !(axis.name in view.slice))
      .map((axis) => axis.name);
    const seriesCurves = curvesAlong(grid.grid_points, { ...along, yOf: resultsIn });
    const pooled = view.names.searched(searchedAxis)
      ? seriesCurves.flatMap((curve) => curveBins(curve, searchedAxis).map((bin) => bin.row)) : null;
    flags.draw(grid, { slice: view.slice, shownAxes, names: view.names, pooled });
    await drawFragments(grid.study, seriesCurves, view).catch((error) => {
      replaceChildren(fragments.chart, el('p', { class: 'note' }, error.message));
    });
  }

  // `names`: the study's axes as the service describes them (axis_names.js AxisNames).
  function currentView(grid, names) {
    const xAxis = state.get('x', defaultXAxis(grid.axes, names));
    return { outcome: state.get('outcome', 'break-up'), xAxis, slice: currentSlice(state, grid.axes, xAxis, names),
      names,
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
