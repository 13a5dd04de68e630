// The lookup-table downloads of a study (the export service, GET /api/studies/ID/tables): one link
// per format for the chosen kind of table. Shown once the study has results.
import { el, replaceChildren, select } from '../dom.js';

const kKinds = [['grid', 'grid: per grid point'], ['fit', 'fit: from the fitted curves'],
  ['sections', 'sections: per fragment size section']];
const kFormats = [['csv', 'CSV'], ['dat', '.dat'], ['json', 'JSON'], ['hdf5', 'HDF5'], ['melcor', 'MELCOR']];

export function tablesPanel(studyId) {
  const links = el('p', { id: 'table-links' });
  const drawLinks = (kind) => replaceChildren(links, kFormats.map(([format, label]) => [el('a', {
    href: `/api/studies/${studyId}/tables?format=${format}&kind=${kind}`, download: true, dataset: { format, kind },
  }, label), ' ']));
  drawLinks('grid');
  return el('section', { class: 'panel', id: 'tables-panel' }, el('h2', {}, 'Lookup tables'),
    el('div', { class: 'controls' },
      el('label', {}, 'Table ', select(kKinds, 'grid', drawLinks, { id: 'choose-table-kind' }))),
    links, el('p', { class: 'note' }, 'Tables for system codes, made by the service from the stored results; every ' +
      'column, unit and format: docs/EXPORT.md.'));
}
