// Scales and ticks of the charts: each axis spans its data (not whole decades), ticks sit at the
// data's own values where there are few of them (speeds, N) and at 1-2-5 steps otherwise, and a
// tick label is left out where it would touch its neighbour.
import { formatNumber } from './dom.js';

// Axes with at most this many distinct values get a tick at each value.
const kMaxDataTicks = 12;
// Smallest distance between two tick labels, CSS pixels.
const kLabelGap = 34;

const finite = (values) => values.filter((value) => typeof value === 'number' && Number.isFinite(value));

// [min, max] of `values` widened by `share` of the span on each side (in log for a log axis);
// null without values.
export function paddedRange(values, { log = false, share = 0.05 } = {}) {
  const usable = finite(values).filter((value) => !log || value > 0);
  if (usable.length === 0) return null;
  let [low, high] = [Math.min(...usable), Math.max(...usable)];
  if (log) {
    const factor = Math.max(10 ** (Math.log10(high / low) * share), 1.1);
    return [low / factor, high * factor];
  }
  const span = high - low || Math.abs(high) || 1;
  [low, high] = [low - span * share, high + span * share];
  return [low, high];
}

// Evenly spaced ticks over [low, high] at a 1, 2 or 5 step, about five of them.
function linearTicks(low, high) {
  const rough = (high - low) / 5;
  const magnitude = 10 ** Math.floor(Math.log10(rough));
  const step = [1, 2, 5, 10].map((m) => m * magnitude).find((candidate) => candidate >= rough);
  const ticks = [];
  for (let value = Math.ceil(low / step) * step; value <= high; value += step) ticks.push(Number(value.toPrecision(6)));
  return ticks;
}

// Ticks over [low, high] on a log axis: 1-2-5 steps per decade, or evenly spaced ones where the
// range spans less than a decade or two.
function logTicks(low, high) {
  for (const mantissas of [[1, 2, 5], [1, 2, 3, 5, 7]]) {
    const ticks = [];
    for (let exponent = Math.floor(Math.log10(low)); exponent <= Math.ceil(Math.log10(high)); exponent++)
      for (const mantissa of mantissas) {
        const value = Number((mantissa * 10 ** exponent).toPrecision(6));
        if (value >= low && value <= high) ticks.push(value);
      }
    if (ticks.length >= 4) return ticks;
  }
  return linearTicks(low, high);
}

// The ticks of an axis over [low, high]: the data's distinct values when there are few, else 1-2-5
// steps in log (a linear axis keeps uPlot's own ticks: null).
export function axisTicks(values, [low, high], { log }) {
  const distinct = [...new Set(finite(values))].sort((a, b) => a - b);
  if (distinct.length > 0 && distinct.length <= kMaxDataTicks) return distinct;
  return log ? logTicks(low, high) : null;
}

// uPlot `values` callback: the tick labels, each left empty where it would come closer than
// kLabelGap to the last label shown (along x) or than a line's height (along y).
export function spacedLabels(scaleKey) {
  return (u, splits) => {
    const gap = scaleKey === 'x' ? kLabelGap : 14;
    let last = -Infinity;
    return splits.map((value) => {
      const position = u.valToPos(value, scaleKey);
      if (Math.abs(position - last) < gap) return '';
      last = position;
      return formatNumber(value, 3);
    });
  };
}
