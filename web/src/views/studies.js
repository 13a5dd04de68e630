// The studies list: each study with its progress (counts by status, rate, time left), refreshed
// every two seconds without reloading the page.
import { getJson, query } from '../api.js';
import { el, formatDuration, formatNumber, formatTime, replaceChildren, table } from '../dom.js';
import { progressBar, studyState } from '../progress.js';

const kRefreshMs = 2000;
const kPageSize = 20;

function countsText(counts) {
  return ['queued', 'running', 'done', 'failed', 'cancelled']
    .filter((status) => counts[status] > 0)
    .map((status) => `${counts[status]} ${status}`)
    .join(', ') || 'no cases';
}

const kColumns = [
  { label: 'Study', value: (s) => el('a', { href: `/?study=${s.id}`, 'data-nav': true, class: 'study-name' }, s.name) },
  { label: 'Status', value: (s) => el('span', { class: 'study-state' }, studyState(s)) },
  { label: 'Cases', value: (s) => s.cases, numeric: true },
  { label: 'Progress', value: (s) => progressBar(s.progress) },
  { label: 'Counts', value: (s) => el('span', { class: 'counts' }, countsText(s.progress.counts)) },
  { label: 'Cases/h', value: (s) => el('span', { class: 'rate' }, formatNumber(s.progress.cases_per_hour, 3)),
    numeric: true },
  { label: 'Time left',
    value: (s) => (s.progress.complete || s.status === 'cancelled' ? '–' : formatDuration(s.progress.seconds_left)) },
  { label: 'Submitted', value: (s) => formatTime(s.created_at) },
];

export async function showStudies(view, parameters, { navigate, showNotice }) {
  const offset = Number(parameters.get('offset') || 0);
  const holder = el('div', { id: 'studies' });
  const pager = el('div', { class: 'pager' });
  replaceChildren(view, el('h1', {}, 'Studies'), holder, pager);
  let timer = null;
  let stopped = false;

  async function refresh() {
    try {
      const page = await getJson(`/api/progress${query({ limit: kPageSize, offset })}`);
      if (stopped) return;
      replaceChildren(holder, page.total === 0
        ? el('p', {}, 'No studies yet. ', el('a', { href: '/?submit', 'data-nav': true }, 'Submit one'), '.')
        : table(kColumns, page.items, { id: 'studies-table' }));
      replaceChildren(pager,
        offset > 0 && el('button',
          { onclick: () => navigate(query({ offset: Math.max(0, offset - kPageSize) })) }, '← newer'),
        `${page.total === 0 ? 0 : offset + 1}–${offset + page.items.length} of ${page.total}`,
        offset + kPageSize < page.total && el('button',
          { onclick: () => navigate(query({ offset: offset + kPageSize })) }, 'older →'));
      showNotice('');
    } catch (error) {
      showNotice(`cannot reach the service: ${error.message}`);
    }
    if (!stopped) timer = setTimeout(refresh, kRefreshMs);
  }
  await refresh();
  return () => {
    stopped = true;
    clearTimeout(timer);
  };
}
