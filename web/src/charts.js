// Charts with uPlot (docs/WEB.md). Each curve has a style:
//   measured  points joined by a line, with the 95 % interval of each point as a whisker;
//   points    the same points and whiskers without the line;
//   fitted    a dashed (or dotted: dash 'dotted') line with its 95 % band where it has one;
//   markers   hollow rings (e.g. grid points with flagged results);
//   crossing  a ring filled white at each point with its interval along x (xlo, xhi; null: not
//             bounded, to the plot's edge) as a horizontal bar (e.g. the search's v50).
// Each axis spans the data; a bounded quantity (bounds [0, 1]) keeps its whole range and its
// intervals are clipped to it. The legend (chart_legend.js) hides and shows series. The chart
// keeps its uPlot instance, its curves and its whiskers on the element (element.uplot,
// element.curves, element.whiskers) for the browser tests to read.
import uPlot from '/vendor/uPlot.esm.js';
import { el, replaceChildren } from './dom.js';
import { axisTicks, paddedRange, spacedLabels } from './chart_scales.js';
import { legend } from './chart_legend.js';

const kPalette = ['#1f5fbf', '#c2410c', '#2e7d32', '#7b1fa2', '#00838f', '#b3261e', '#8d6e00', '#455a64',
  '#d81b60', '#5d4037', '#3949ab', '#689f38'];
const kHeight = 300;
const kDashes = { dashed: [7, 4], dotted: [2, 3] };

// The red, green and blue of '#rrggbb' or 'rgb(r, g, b)'.
function channels(color) {
  if (color.startsWith('rgb')) return color.match(/\d+/g).slice(0, 3).map(Number);
  const value = Number.parseInt(color.slice(1), 16);
  return [value >> 16, (value >> 8) & 255, value & 255];
}

function translucent(color, alpha) {
  return `rgba(${channels(color).join(', ')}, ${alpha})`;
}

export const paletteColor = (i) => kPalette[i % kPalette.length];

// `color` mixed with white by `share` (0: the colour, 1: white).
function lighter(color, share) {
  return `rgb(${channels(color).map((channel) => Math.round(channel + (255 - channel) * share)).join(', ')})`;
}

// Colours of curves grouped by up to two axes (curve.groupValues): one hue per value of one axis
// and, where there is a second (`shadeFirst` where it is one of the two, N say), lighter shades
// for its smaller values; a curve keeps its colour in every plot of the page.
export function colourGroups(curves, shadeFirst = null) {
  const keys = Object.keys((curves[0] || {}).groupValues || {});
  const shadeAxis = keys.length === 2 ? (keys.includes(shadeFirst) ? shadeFirst : keys[0]) : null;
  const hueAxis = keys.find((key) => key !== shadeAxis);
  const values = (axis) => [...new Set(curves.map((curve) => JSON.stringify(curve.groupValues[axis])))].sort((a, b) =>
    (JSON.parse(a) < JSON.parse(b) ? -1 : 1));
  const [hues, shades] = [values(hueAxis), shadeAxis ? values(shadeAxis) : []];
  for (const curve of curves) {
    const hue = paletteColor(Math.max(0, hues.indexOf(JSON.stringify(curve.groupValues[hueAxis]))));
    const shade = shadeAxis ? shades.indexOf(JSON.stringify(curve.groupValues[shadeAxis])) : 0;
    curve.color = shadeAxis && shades.length > 1
      ? lighter(hue, (0.5 * (shades.length - 1 - shade)) / (shades.length - 1)) : hue;
  }
  return curves;
}

// Gives each curve without a colour the next one of the palette, and without a style 'measured'.
export function assignColors(curves) {
  curves.forEach((curve, i) => {
    curve.color = curve.color || paletteColor(i);
    curve.style = curve.style || 'measured';
  });
  return curves;
}

const clip = (value, bounds) => (value === null || value === undefined || !bounds ? value
  : Math.min(bounds[1], Math.max(bounds[0], value)));

// Aligned data for uPlot: the union of x values and, per curve, a column of one field (clipped to
// `bounds`) at each x, null where the curve has no point; each column is filled from the curve's
// points through an index of x (no search per x).
function aligner(curves, bounds) {
  const xs = [...new Set(curves.flatMap((curve) => curve.points.map((point) => point.x)))].sort((a, b) => a - b);
  const index = new Map(xs.map((x, i) => [x, i]));
  const column = (curve, field) => {
    const values = new Array(xs.length).fill(null);
    for (const point of curve.points) {
      const value = point[field];
      if (value !== null && value !== undefined) values[index.get(point.x)] = clip(value, bounds);
    }
    return values;
  };
  return { xs, column };
}

const hasIntervals = (curve) => curve.points.some((point) =>
  typeof point.lo === 'number' && typeof point.hi === 'number');

function lineSeries(curve) {
  const { color, style } = curve;
  const base = { label: curve.label, stroke: color, spanGaps: true };
  const none = () => null;
  const dash = kDashes[curve.dash || 'dashed'];
  if (style === 'fitted') return { ...base, width: 1.75, dash, points: { show: false } };
  const ring = { show: true, size: 13, width: 2, stroke: color, fill: 'transparent' };
  if (style === 'markers') return { ...base, paths: none, points: ring };
  if (style === 'crossing') return { ...base, paths: none, points: { ...ring, size: 11, width: 2.5, fill: '#fff' } };
  return { ...base, width: 2, paths: style === 'points' ? none : undefined,
    points: { show: true, size: 7, fill: color, stroke: color } };
}

// uPlot's series, bands and data columns, and per measured curve with intervals its whiskers;
// and per crossing curve its bars; curve.series lists the uPlot series indices that draw it (for the
// legend's toggle).
function seriesOptions(curves, data) {
  const series = [{}];
  const bands = [];
  const columns = [data.xs];
  const whiskers = [];
  const bars = [];
  for (const curve of curves) {
    curve.series = [series.length];
    series.push(lineSeries(curve));
    columns.push(data.column(curve, 'y'));
    if (curve.style === 'crossing') {
      bars.push({ series: curve.series[0], color: curve.color, points: curve.points });
      continue;
    }
    if (!hasIntervals(curve) || curve.style === 'markers') continue;
    if (curve.style === 'fitted') {
      for (const bound of ['upper', 'lower']) {
        curve.series.push(series.length);
        series.push({ label: `${curve.label} (${bound} 95 %)`, stroke: 'transparent', width: 0, spanGaps: true,
          points: { show: false } });
      }
      columns.push(data.column(curve, 'hi'), data.column(curve, 'lo'));
      bands.push({ series: [series.length - 2, series.length - 1], fill: translucent(curve.color, 0.13) });
    } else {
      whiskers.push({ series: curve.series[0], label: curve.label, color: translucent(curve.color, 0.75),
        lo: data.column(curve, 'lo'), hi: data.column(curve, 'hi') });
    }
  }
  return { series, bands, columns, whiskers, bars };
}

// Strokes, clipped to the plot area, the path `trace(item)` of each item whose series is shown
// (item.series, its colour item.color), `width` CSS pixels wide.
function strokeInPlot(u, items, width, trace) {
  const ctx = u.ctx;
  const { left, top, width: areaWidth, height } = u.bbox;
  ctx.save();
  ctx.beginPath();
  ctx.rect(left, top, areaWidth, height);
  ctx.clip();
  ctx.lineWidth = width * (uPlot.pxRatio || 1);
  for (const item of items) {
    if (!u.series[item.series].show) continue;
    ctx.strokeStyle = item.color;
    ctx.beginPath();
    trace(ctx, item);
    ctx.stroke();
  }
  ctx.restore();
}

// Draws each shown measured series' intervals as vertical whiskers with caps, inside the plot area.
function drawWhiskers(u, whiskers, log) {
  const cap = 3 * (uPlot.pxRatio || 1);
  const floor = (value) => (log ? Math.max(value, u.scales.y.min) : value);
  strokeInPlot(u, whiskers, 1.25, (ctx, whisker) => u.data[0].forEach((x, i) => {
    if (whisker.lo[i] === null || whisker.hi[i] === null) return;
    const px = u.valToPos(x, 'x', true);
    const [low, high] = [u.valToPos(floor(whisker.lo[i]), 'y', true), u.valToPos(floor(whisker.hi[i]), 'y', true)];
    ctx.moveTo(px, low);
    ctx.lineTo(px, high);
    ctx.moveTo(px - cap, low);
    ctx.lineTo(px + cap, low);
    ctx.moveTo(px - cap, high);
    ctx.lineTo(px + cap, high);
  }));
}

// Draws each shown crossing's interval along x as a bar with caps at its point's height; an end
// that is not bounded (null) reaches the plot's edge.
function drawBars(u, bars) {
  const cap = 4 * (uPlot.pxRatio || 1);
  const { left, width } = u.bbox;
  strokeInPlot(u, bars, 2.5, (ctx, bar) => {
    for (const point of bar.points) {
      const py = u.valToPos(point.y, 'y', true);
      const from = point.xlo === null ? left : u.valToPos(point.xlo, 'x', true);
      const to = point.xhi === null ? left + width : u.valToPos(point.xhi, 'x', true);
      ctx.moveTo(from, py);
      ctx.lineTo(to, py);
      for (const end of [from, to]) {
        ctx.moveTo(end, py - cap);
        ctx.lineTo(end, py + cap);
      }
    }
  });
}

// The y range: the bounds when given (with a little room), else the data's span, with their
// intervals unless `fitIntervals` is false (then an interval reaching far out is cut at the edge).
function yRange(curves, { bounds, yLog, fitIntervals }) {
  if (bounds) {
    const room = (bounds[1] - bounds[0]) * 0.03;
    return [bounds[0] - room, bounds[1] + room];
  }
  const values = curves.flatMap((curve) => curve.points.flatMap((point) =>
    (fitIntervals && curve.style !== 'markers' ? [point.y, point.lo, point.hi] : [point.y])));
  return paddedRange(values, { log: yLog, share: 0.06 }) || [0, 1];
}

// 1-2-5 ticks over the y scale's current range.
const logTicksOf = (u) => axisTicks([], [u.scales.y.min, u.scales.y.max], { log: true });

// The x axis spans every curve; its ticks sit at the measured x values (a fitted curve's many
// points would hide them), or at 1-2-5 steps without `dataTicks` (x values that are not the
// tested ones: bins of a searched axis).
function axisOptions(curves, data, { xLabel, yLabel, xLog, yLog, dataTicks = true }) {
  const xRange = paddedRange(data.xs, { log: xLog, share: 0.04 }) || [0, 1];
  const measured = dataTicks ? curves.filter((curve) => curve.style !== 'fitted')
    .flatMap((curve) => curve.points.map((point) => point.x)) : [];
  const xTicks = axisTicks(measured.length || !dataTicks ? measured : data.xs, xRange, { log: xLog });
  // `filter` keeps every tick (uPlot's own thins a log axis's ticks to whole decades).
  const keepAll = (u, splits) => splits;
  const x = { label: xLabel, values: spacedLabels('x'), filter: keepAll, ...(xTicks ? { splits: () => xTicks } : {}) };
  const y = { label: yLabel, size: 58, values: spacedLabels('y'),
    ...(yLog ? { filter: keepAll, splits: (u) => logTicksOf(u) } : {}) };
  return { xRange, axes: [x, y] };
}

// Each chart follows its container's width; the width last seen is kept on the container, so that
// a chart drawn again needs no layout of the page to size itself.
const resizer = new ResizeObserver((entries) => {
  for (const { target, contentRect } of entries) {
    target.knownWidth = contentRect.width;
    const width = Math.max(320, Math.floor(contentRect.width) - 8);
    if (target.uplot && Math.abs(target.uplot.width - width) > 2) target.uplot.setSize({ width, height: kHeight });
  }
});

// Draws `curves` ([{label, points: [{x, y, lo, hi}], style, dash, color}]) into `container`.
// `bounds`: the quantity's range, e.g. [0, 1]; `empty`: what to say when there is nothing to draw.
// `dataTicks` false: ticks at 1-2-5 steps, not at the curves' x values.
export function plotCurves(container, curves, options) {
  const { xLabel, yLabel, xLog = true, yLog = false, bounds = null, fitIntervals = true } = options;
  const { empty = 'Nothing to plot yet: no finished cases here.' } = options;
  if (container.uplot) container.uplot.destroy();
  container.uplot = null;
  container.curves = curves;
  container.dataset.series = curves.length;
  container.dataset.points = curves.reduce((sum, curve) => sum + curve.points.length, 0);
  if (curves.length === 0) {
    replaceChildren(container, el('p', { class: 'note' }, empty));
    return;
  }
  assignColors(curves);
  const data = aligner(curves, bounds);
  const logX = xLog && data.xs.every((x) => x > 0);
  const { series, bands, columns, whiskers, bars } = seriesOptions(curves, data);
  const { xRange, axes } = axisOptions(curves, data, { ...options, xLog: logX });
  const holder = el('div', { class: 'plot' });
  const toggle = (curve, shown) => curve.series.forEach((index) => container.uplot.setSeries(index, { show: shown }));
  replaceChildren(container, holder, legend(curves, toggle));
  const chartOptions = {
    width: Math.max(320, (container.knownWidth || container.clientWidth || 600) - 8), height: kHeight,
    legend: { show: false },
    scales: {
      x: { time: false, distr: logX ? 3 : 1, range: () => xRange },
      y: { distr: yLog ? 3 : 1, range: () => yRange(curves, { bounds, yLog, fitIntervals }) },
    },
    axes, series, bands, cursor: { drag: { x: false, y: false } },
    hooks: { draw: [(u) => drawWhiskers(u, whiskers, yLog), (u) => drawBars(u, bars)] },
  };
  container.whiskers = whiskers;
  container.uplot = new uPlot(chartOptions, columns, holder);
  resizer.observe(container);
}
