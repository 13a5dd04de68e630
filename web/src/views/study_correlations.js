// The correlations panel of a study page: for the plotted outcome, x and slice, each group's fitted
// critical values v10, v50, v90 with their 95 % intervals and the fit's status, and the scaling
// exponents of v50 (docs/CORRELATIONS.md).
import { el, formatNumber, replaceChildren, table } from '../dom.js';
import { axisLabel } from '../series.js';
import { kLevelNames } from '../correlations.js';

const interval = (critical) => (critical && typeof critical.estimate === 'number'
  ? `${formatNumber(critical.estimate)} [${(critical.ci95 || []).map((v) => formatNumber(v)).join(', ')}]` : '–');

function criticalColumns(shownAxes) {
  return [
    ...shownAxes.map((axis) => ({ label: axisLabel(axis), value: (fit) => formatNumber(fit.group[axis], 4), numeric: true })),
    { label: 'fit', value: (fit) => fit.name }, { label: 'status', value: (fit) => fit.status },
    { label: 'cases', value: (fit) => fit.cases, numeric: true },
    ...Object.entries(kLevelNames).map(([level, name]) => ({
      label: `${name} (95 %)`, value: (fit) => interval((fit.critical || []).find((c) => String(c.level) === level)), numeric: true })),
  ];
}

function scalingText(fit) {
  if (!fit || !fit.exponents) return null;
  const terms = Object.entries(fit.exponents).map(([axis, e]) =>
    `${axisLabel(axis)}^${formatNumber(e.estimate)} [${e.ci95.map((v) => formatNumber(v)).join(', ')}]`);
  return el('p', { id: 'correlations-scaling' }, `Scaling of v50 (${fit.status}): v50 ∝ ${terms.join(' · ')} (95 % intervals).`);
}

export function createCorrelationsPanel() {
  const body = el('div');
  const node = el('section', { class: 'panel', id: 'panel-correlations', hidden: true }, el('h2', {}, 'Correlations'), body,
    el('p', { class: 'note' }, 'Per group: logistic regression of the outcome against the log of the dose; critical values where ' +
      'the fitted probability crosses 0.1, 0.5 and 0.9, with 95 % profile-likelihood intervals (docs/CORRELATIONS.md).'));
  function draw(correlations, { outcome, xAxis, slice }) {
    node.hidden = !correlations;
    if (!correlations) return;
    const fits = correlations.groupFits(outcome, xAxis, slice);
    const shownAxes = fits.length ? Object.keys(fits[0].group).filter((axis) => !(axis in slice)) : [];
    replaceChildren(body, fits.length === 0 ? el('p', { class: 'note' }, `No fit of ${outcome} along ${axisLabel(xAxis)}.`)
      : table(criticalColumns(shownAxes), fits, { id: 'correlations-table' }), scalingText(correlations.scaling(outcome, slice)));
  }
  return { node, draw };
}
