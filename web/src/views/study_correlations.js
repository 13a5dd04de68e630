// The correlations panel of a study page: for the plotted outcome, x and slice, each group's fitted
// critical values v10, v50, v90 with their 95 % intervals and the fit's status, a warning for each
// value the data do not pin down (its estimate outside the tested doses, or its interval reaching
// far beyond them), and the scaling exponents of v50 (docs/CORRELATIONS.md).
import { el, formatNumber, replaceChildren, table } from '../dom.js';
import { extrapolations, kFarBeyond, kLevels, levelName } from '../correlations.js';
import { unitText } from '../units.js';

function interval(critical, warning) {
  if (!critical || typeof critical.estimate !== 'number') return '–';
  const text = `${formatNumber(critical.estimate)} [${(critical.ci95 || []).map((v) => formatNumber(v)).join(', ')}]`;
  return warning ? [text, ' ', el('span', { class: 'warning-mark', title: warning }, '⚠')] : text;
}

// The table's columns; axes named in `names` (axis_names.js AxisNames), the critical values in the
// unit of the dose's axis.
function criticalColumns(shownAxes, { names, dose }, warningOf) {
  const unit = names.unit(dose) ? ` (${unitText(names.unit(dose))})` : '';
  return [
    ...shownAxes.map((axis) => ({ label: names.label(axis), value: (fit) => formatNumber(fit.group[axis], 4),
      numeric: true })),
    { label: 'fit', value: (fit) => fit.name }, { label: 'status', value: (fit) => fit.status },
    { label: 'cases', value: (fit) => fit.cases, numeric: true },
    ...kLevels.map((level) => ({
      label: `${levelName(level, dose)}${unit}, 95 %`, numeric: true,
      value: (fit) => interval((fit.critical || []).find((c) => c.level === level), warningOf(fit, levelName(level,
        dose))) })),
  ];
}

const intervalText = (bounds) => (bounds || []).map((v) => formatNumber(v)).join(', ');
const groupText = (group, names) => Object.entries(group).map(([axis,
  value]) => `${names.label(axis)} = ${value}`).join(', ');

// One line per extrapolated critical value.
function warningLines(found, names, doseUnit) {
  if (found.length === 0) return null;
  const text = ({ fit, level, critical, range }) => {
    const [lo, hi] = critical.ci95 || [];
    const where = groupText(fit.group, names);
    const value = `${formatNumber(critical.estimate)} [${formatNumber(lo)}, ${formatNumber(hi)}]${doseUnit}`;
    const tested = `${formatNumber(range[0])}–${formatNumber(range[1])}${doseUnit}`;
    return `${level}${where ? ` at ${where}` : ''}: ${value}, beyond the tested ${tested}: ` +
      'an extrapolation, not a measurement.';
  };
  return el('ul', { class: 'warnings', id: 'correlations-warnings' }, found.map((entry) => el('li', {}, '⚠ ',
    text(entry))));
}

// "v50 ∝ N^e [lo, hi]" for each scaling fit that has exponents; nothing for those without.
function scalingLines(fits, names) {
  const lines = fits.filter((fit) => fit.exponents && Object.keys(fit.exponents).length > 0).map((fit) => {
    const terms = Object.entries(fit.exponents).map(([axis, e]) =>
      `${names.symbol(axis)}^${formatNumber(e.estimate)} [${intervalText(e.ci95)}]`);
    const where = groupText(fit.group || {}, names);
    return el('p', { class: 'scaling' },
      `Scaling of v50${where ? ` at ${where}` : ''} (${fit.status}): v50 ∝ ${terms.join(' · ')} ` +
      '(exponents with 95 % intervals).');
  });
  return lines.length ? el('div', { id: 'correlations-scaling' }, lines) : null;
}

export function createCorrelationsPanel() {
  const body = el('div');
  const note = el('p', { class: 'note' }, 'Per group: logistic regression of the outcome against the log of the ' +
    'dose; critical values where the fitted probability crosses 0.1, 0.5 and 0.9, with 95 % profile-likelihood ' +
    'intervals (docs/CORRELATIONS.md). ⚠: the estimate lies outside the tested range of the dose, or its interval ' +
    `reaches more than ${kFarBeyond} times beyond it.`);
  const node = el('section', { class: 'panel', id: 'panel-correlations', hidden: true },
    el('h2', {}, 'Correlations'), body, note);

  // Returns the extrapolated critical values drawn (for the critical-speed plot's note).
  function draw(correlations, { outcome, xAxis, slice, names }) {
    node.hidden = !correlations;
    if (!correlations) return [];
    const fits = correlations.groupFits(outcome, xAxis, slice);
    const found = extrapolations(fits);
    const warningOf = (fit, level) => {
      const entry = found.find((f) => f.fit === fit && f.level === level);
      return entry && `beyond the tested ${formatNumber(entry.range[0])}–${formatNumber(entry.range[1])}`;
    };
    const doseUnit = names.unit(xAxis) ? ` ${unitText(names.unit(xAxis))}` : '';
    const shownAxes = fits.length ? Object.keys(fits[0].group).filter((axis) => !(axis in slice)) : [];
    replaceChildren(body, fits.length === 0 ? el('p', { class: 'note' },
      `No fit of ${outcome} along ${names.label(xAxis)}.`)
      : table(criticalColumns(shownAxes, { names, dose: xAxis }, warningOf), fits, { id: 'correlations-table' }),
    warningLines(found, names, doseUnit), scalingLines(correlations.scalings(outcome, slice), names));
    return found;
  }
  return { node, draw };
}
