// A study's progress as the page shows it: a bar of done, failed and running cases, and its state
// in a word: cancelled, complete (every case finished), running or queued. The API's study status
// only says whether the study was cancelled ("active" otherwise, finished or not).
import { el } from './dom.js';

export function progressBar(progress) {
  const counts = progress.counts;
  const total = Math.max(1, progress.total - counts.cancelled);
  const bar = el('div', { class: 'progress', role: 'progressbar', 'aria-valuemin': 0, 'aria-valuemax': total,
    'aria-valuenow': counts.done + counts.failed,
    title: `${counts.done} done, ${counts.failed} failed, ${counts.running} running of ${total}` });
  for (const status of ['done', 'failed', 'running']) {
    const part = el('span', { class: status });
    part.style.width = `${(100 * counts[status]) / total}%`;
    bar.append(part);
  }
  return bar;
}

export function studyState(study) {
  if (study.status === 'cancelled') return 'cancelled';
  if (study.progress.complete) return 'complete';
  return study.progress.counts.running > 0 ? 'running' : 'queued';
}
