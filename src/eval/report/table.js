// The metrics tables: sortable by column, worst first, with what the reference's noise cannot rank.

// How bad a value is, so that every column sorts worst first on the first click.
function badness(column, row) {
  const v = row[column.key];
  if (column.better === 'higher') return -v;
  if (column.better === 'one') return Math.abs(v - 1);
  return v;
}

// Twice the noise a difference between rows a and b of this column must exceed to rank them;
// null where the column has no noise to judge by.
function tolerance(column, a, b) {
  if (typeof column.noise === 'number') return 2 * column.noise;
  if (column.error_key) return 2 * Math.hypot(a[column.error_key], b[column.error_key]);
  return null;
}

function tieText(column, tol) {
  const within = typeof column.noise === 'number' ?
      'twice ' + column.noise_label + ' (2 x ' + formatted(column.noise, 3) + ' = ' + formatted(tol, 3) + ')' :
      'twice the two rows\u2019 combined standard error (' + formatted(tol, 3) + ')';
  return 'The difference to the row above is within ' + within + ': not a ranking.';
}

function metricsTable(run) {
  const spec = run.table;
  const state = {key: spec.sort, worstFirst: true};
  const table = el('table', {class: 'metrics'});
  const headRow = el('tr');
  for (const c of spec.columns) {
    const th =
        el('th', {title: c.better ? 'click: sort worst to best, again: best to worst' : 'click: sort by name'}, c.label,
           el('span', {class: 'arrow'}));
    th.dataset.key = c.key;
    th.tabIndex = 0;
    const sortBy = () => {
      state.worstFirst = state.key === c.key ? !state.worstFirst : true;
      state.key = c.key;
      fill();
    };
    th.addEventListener('click', sortBy);
    th.addEventListener('keydown', (e) => {
      if (e.key === 'Enter' || e.key === ' ') {
        e.preventDefault();
        sortBy();
      }
    });
    headRow.append(th);
  }
  const body = el('tbody');
  table.append(el('thead', null, headRow), body);
  if (spec.floors.length) {
    const foot = el('tfoot');
    for (const f of spec.floors) {
      const tr = el('tr');
      for (const c of spec.columns)
        tr.append(
            el('td',
               {text: c.key === 'method' ? f.label : (c.key in f.values ? formatted(f.values[c.key], c.digits) : '')}));
      foot.append(tr);
    }
    table.append(foot);
  }
  function fill() {
    const column = spec.columns.find((c) => c.key === state.key);
    const rows = spec.rows.slice();
    if (column.key === 'method')
      rows.sort((a, b) => a.method.localeCompare(b.method) * (state.worstFirst ? 1 : -1));
    else
      rows.sort((a, b) => (badness(column, b) - badness(column, a)) * (state.worstFirst ? 1 : -1));
    body.replaceChildren();
    rows.forEach((row, i) => {
      const tr = el('tr', {class: row.muted ? 'muted' : ''});
      for (const c of spec.columns) {
        if (c.key === 'method') {
          tr.append(el('td', {text: row.method}));
          continue;
        }
        const td = el('td', {text: formatted(row[c.key], c.digits)});
        if (c.error_key) td.append(el('span', {class: 'pm', text: ' \u00b1' + formatted(row[c.error_key], 2)}));
        const tol = i > 0 && c === column ? tolerance(c, row, rows[i - 1]) : null;
        if (tol !== null && Math.abs(badness(c, row) - badness(c, rows[i - 1])) <= tol)
          td.append(el('span', {class: 'tie', title: tieText(c, tol), text: '\u2248'}));
        tr.append(td);
      }
      body.append(tr);
    });
    for (const th of headRow.children) {
      const on = th.dataset.key === state.key;
      th.classList.toggle('sorted', on);
      th.querySelector('.arrow').textContent =
          on ? (state.worstFirst ? ' \u25bc worst first' : ' \u25b2 best first') : '';
    }
  }
  fill();
  return el('div', {class: 'table-box'}, table);
}

// One line on the default column: the best row, the next, and whether the gap is a ranking.
function rankingNote(run) {
  const spec = run.table;
  const column = spec.columns.find((c) => c.key === spec.sort);
  const rows = spec.rows.filter((r) => !r.muted).sort((a, b) => badness(column, a) - badness(column, b));
  if (rows.length < 2) return null;
  const [best, next] = rows;
  const gap = Math.abs(badness(column, next) - badness(column, best));
  const tol = tolerance(column, best, next);
  let verdict = '';
  if (tol !== null)
    verdict = gap > tol ? ' The gap is larger than twice ' + (column.noise_label || 'the standard errors') + ' (' +
            formatted(tol, 3) + ').' :
                          ' The gap is within twice ' + (column.noise_label || 'the standard errors') + ' (' +
            formatted(tol, 3) + '): not a ranking.';
  return el(
      'p', {class: 'ranking'}, 'Best ' + column.label + ': ', el('b', {text: best.method}),
      ' (' + formatted(best[column.key], column.digits) + '); next ', el('b', {text: next.method}),
      ' (' + formatted(next[column.key], column.digits) + ').' + verdict);
}

function tableNotes(run) {
  const lines = [];
  const seen = new Set();
  for (const c of run.table.columns) {
    if (typeof c.noise === 'number' && !seen.has(c.noise_label)) {
      seen.add(c.noise_label);
      lines.push('\u2248 in ' + c.label + ': ' + tieText(c, 2 * c.noise));
    } else if (c.error_key && !seen.has('error')) {
      seen.add('error');
      lines.push(
          '\u00b1: the standard error from the reference\u2019s noise; \u2248 in ' + c.label +
          ': within twice the two rows\u2019 combined standard error of the row above, not a ranking.');
    }
  }
  lines.push('Click a column to sort by it, worst first; click again for best first. Every method is listed.');
  return el('div', null, ...lines.map((t) => el('p', {class: 'legend-note', text: t})));
}
