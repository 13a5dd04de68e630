// The dashboard's router: the URL's query says which view to show (?study=ID, ?case=ID, ?submit,
// nothing: the studies list) and with which choices, so that every view is a permalink.
import { replaceChildren } from './dom.js';
import { showStudies } from './views/studies.js';
import { showStudy } from './views/study.js';
import { showCase } from './views/case.js';
import { showSubmit } from './views/submit.js';

const view = document.getElementById('view');
const notice = document.getElementById('notice');
let leaveView = null;

function chooseView(parameters) {
  if (parameters.has('study')) return showStudy;
  if (parameters.has('case')) return showCase;
  if (parameters.has('submit')) return showSubmit;
  return showStudies;
}

export function navigate(search, { replace = false } = {}) {
  const url = `/${search}`;
  if (replace) history.replaceState(null, '', url);
  else history.pushState(null, '', url);
  render();
}

export function showNotice(text) {
  notice.textContent = text || '';
}

async function render() {
  if (leaveView) leaveView();
  leaveView = null;
  showNotice('');
  const parameters = new URLSearchParams(location.search);
  const show = chooseView(parameters);
  replaceChildren(view);
  try {
    leaveView = await show(view, parameters, { navigate, showNotice });
  } catch (error) {
    replaceChildren(view);
    showNotice(error.message);
  }
}

document.addEventListener('click', (event) => {
  const link = event.target.closest('a[data-nav]');
  if (!link || event.ctrlKey || event.metaKey || event.shiftKey || event.button !== 0) return;
  event.preventDefault();
  navigate(new URL(link.href).search);
});
window.addEventListener('popstate', render);
render();
