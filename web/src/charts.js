// Charts with uPlot: curves with their 95 % bands, or points; a legend of our own (one entry per
// curve). The chart keeps its uPlot instance and its curves on the element (element.uplot,
// element.curves) for the browser tests to read.
import uPlot from '/vendor/uPlot.esm.js';
import { el, replaceChildren } from './dom.js';

const kPalette = ['#1f5fbf', '#c2410c', '#2e7d32', '#7b1fa2', '#b3261e', '#00838f', '#8d6e00', '#455a64',
  '#d81b60', '#5d4037', '#3949ab', '#689f38'];
const kHeight = 280;

function translucent(color, alpha) {
  const value = Number.parseInt(color.slice(1), 16);
  return `rgba(${value >> 16}, ${(value >> 8) & 255}, ${value & 255}, ${alpha})`;
}

// Aligned data for uPlot: the union of x values and, per curve, y (and its bounds) at each x.
function alignedData(curves) {
  const xs = [...new Set(curves.flatMap((curve) => curve.points.map((point) => point.x)))].sort((a, b) => a - b);
  const column = (curve, field) => {
    const byX = new Map(curve.points.map((point) => [point.x, point[field]]));
    return xs.map((x) => (byX.has(x) && byX.get(x) !== undefined ? byX.get(x) : null));
  };
  return { xs, column };
}

// Gives each curve without a colour the next one of the palette.
export function assignColors(curves) {
  curves.forEach((curve, i) => {
    curve.color = curve.color || kPalette[i % kPalette.length];
  });
  return curves;
}

function seriesOptions(curves, { withBands, pointsOnly, data }) {
  const series = [{}];
  const bands = [];
  const columns = [data.xs];
  assignColors(curves).forEach((curve) => {
    const color = curve.color;
    columns.push(data.column(curve, 'y'));
    series.push({
      label: curve.label, stroke: color, width: curve.dashed ? 1.5 : 2, dash: curve.dashed ? [6, 4] : undefined,
      spanGaps: true, paths: pointsOnly || curve.pointsOnly ? () => null : undefined,
      points: curve.hollow ? { show: true, size: 12, width: 2, stroke: color, fill: 'transparent' }
        : { show: !curve.dashed, size: 6, fill: color },
    });
    if (!withBands || !curve.points.some((point) => point.lo !== null && point.lo !== undefined)) return;
    columns.push(data.column(curve, 'hi'), data.column(curve, 'lo'));
    for (const bound of ['upper', 'lower'])
      series.push({ label: `${curve.label} (${bound} 95 %)`, stroke: translucent(color, 0.35), width: 1, spanGaps: true, points: { show: false } });
    bands.push({ series: [series.length - 2, series.length - 1], fill: translucent(color, 0.12) });
  });
  return { series, bands, columns };
}

function legend(curves) {
  return el('ul', { class: 'legend' }, curves.map((curve) => {
    const swatch = el('span', { class: 'swatch' });
    swatch.style.background = curve.color;
    return el('li', { dataset: { points: curve.points.length } }, swatch, curve.label);
  }));
}

// Draws `curves` ([{label, points: [{x, y, lo, hi}], dashed, pointsOnly, hollow}]) into `container`.
export function plotCurves(container, curves, { xLabel, yLabel, xLog = true, yLog = false, yRange, withBands = true, pointsOnly = false }) {
  if (container.uplot) container.uplot.destroy();
  container.uplot = null;
  container.curves = curves;
  container.dataset.series = curves.length;
  container.dataset.points = curves.reduce((sum, curve) => sum + curve.points.length, 0);
  if (curves.length === 0) {
    replaceChildren(container, el('p', { class: 'note' }, 'Nothing to plot yet: no finished cases here.'));
    return;
  }
  const data = alignedData(curves);
  const { series, bands, columns } = seriesOptions(curves, { withBands, pointsOnly, data });
  const holder = el('div', { class: 'plot' });
  replaceChildren(container, holder, legend(curves));
  const logX = xLog && data.xs.every((x) => x > 0);
  const options = {
    width: Math.max(320, (container.clientWidth || 600) - 8), height: kHeight, legend: { show: false },
    scales: { x: { time: false, distr: logX ? 3 : 1 }, y: yRange ? { range: yRange } : { distr: yLog ? 3 : 1 } },
    axes: [{ label: xLabel }, { label: yLabel }], series, bands, cursor: { drag: { x: false, y: false } },
  };
  container.uplot = new uPlot(options, columns, holder);
}
