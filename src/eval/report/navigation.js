// The overview of every run, and which section is shown (index.html#run/<id>).

function overview() {
  const rows = data.runs.map((run) => {
    const column = run.table.columns.find((c) => c.key === run.table.sort);
    const ranked = run.table.rows.filter((r) => !r.muted).sort((a, b) => badness(column, a) - badness(column, b));
    const [best, next] = ranked;
    let verdict = '';
    if (best && next) {
      const tol = tolerance(column, best, next);
      if (tol !== null)
        verdict = Math.abs(badness(column, next) - badness(column, best)) > tol ? 'ranked' : 'not a ranking';
    }
    return el(
        'tr', null, el('td', null, el('a', {href: '#run/' + run.id, text: run.id})), el('td', {text: run.kind}),
        el('td', {text: run.scene}), el('td', {text: run.width + ' x ' + run.height}),
        el('td', {text: String(run.table.rows.length)}), el('td', {text: column.label}),
        el('td', {text: best ? best.method : ''}), el('td', {text: next ? next.method : ''}),
        el('td', {text: verdict}));
  });
  const head =
      el('tr', null,
         ...['run', 'kind', 'scene', 'size', 'rows', 'by', 'best', 'next', 'best vs next'].map(
             (h) => el('th', {text: h})));
  return el(
      'section', {id: 'overview'}, el('h2', {text: 'Every run'}), el('p', {
        class: 'note',
        text: data.runs.length +
            ' runs. "not a ranking": the best and the next differ by less than twice the reference\u2019s noise (or the flicker floor).'
      }),
      el('table', {class: 'metrics overview'}, el('thead', null, head), el('tbody', null, ...rows)));
}

function activate(section) {
  section.querySelectorAll('[data-src]').forEach((e) => {
    if (e.getAttribute('src') !== e.dataset.src) e.src = e.dataset.src;
    if (e.tagName === 'VIDEO' && e.preload === 'none') e.preload = 'metadata';
  });
}

function show(id) {
  let section = id === null ? document.getElementById('overview') : sections.get(id);
  if (!section) {
    const run = data.runs.find((r) => r.id === id);
    if (!run) return show(null);
    section = draw(run);
    sections.set(id, section);
    main.append(section);
  }
  for (const s of main.children) s.classList.toggle('shown', s === section);
  document.querySelectorAll('#run-list a').forEach((a) => a.classList.toggle('current', a.dataset.id === id));
  activate(section);
  return section;
}

function route() {
  const hash = decodeURIComponent(location.hash.slice(1));
  show(hash.startsWith('run/') ? hash.slice(4) : null);
}
