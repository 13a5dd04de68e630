// The lookup-table downloads of a study (the export service, GET /api/studies/ID/tables): one link
// per format for the chosen kind of table. Shown once the study has results.
import { el, replaceChildren, select } from '../dom.js';

const kKinds = [['grid', 'grid: per grid point'], ['fit', 'fit: from the fitted curves'],
  ['sections', 'sections: per fragment size section']];
const kFormats = [['csv', 'CSV'], ['dat', '.dat'], ['json', 'JSON'], ['hdf5', 'HDF5'], ['melcor', 'MELCOR']];
const kNote = 'Tables for system codes, made by the service from the stored results; every column, unit and ' +
  'format: docs/EXPORT.md.';
// An adaptive search (docs/ADAPTIVE.md) places one or a few cases at each speed: a grid table of it has a
// row per speed, each a probability of 0 or 1 with a wide interval, and the fitted curves are what a
// system code should read (docs/EXPORT.md, "An adaptive search's tables").
const kSearchedNote = ' The speed was searched: the grid table has a row per speed the search ran, with one or a ' +
  'few results each; the fit table, from the fitted curves, is the one for a system code.';

// `searched`: the study has an adaptive search's axis; the fit table is then offered first.
export function tablesPanel(studyId, { searched = false } = {}) {
  const links = el('p', { id: 'table-links' });
  const drawLinks = (kind) => replaceChildren(links, kFormats.map(([format, label]) => [el('a', {
    href: `/api/studies/${studyId}/tables?format=${format}&kind=${kind}`, download: true, dataset: { format, kind },
  }, label), ' ']));
  const kinds = searched
    ? kKinds.map(([kind, label]) => [kind, kind === 'grid' ? 'grid: per searched speed (few results each)' : label])
    : kKinds;
  const first = searched ? 'fit' : 'grid';
  drawLinks(first);
  return el('section', { class: 'panel', id: 'tables-panel' }, el('h2', {}, 'Lookup tables'),
    el('div', { class: 'controls' },
      el('label', {}, 'Table ', select(kinds, first, drawLinks, { id: 'choose-table-kind' }))),
    links, el('p', { class: 'note' }, kNote + (searched ? kSearchedNote : '')));
}
