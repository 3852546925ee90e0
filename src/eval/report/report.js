'use strict';
// glintlab report: draws each run's section from the data glintlab wrote into this page (tables
// sortable by column, the reference/method slider, labelled worst-region crops, videos, plots).
// index.html#selftest checks the page as a person would see it and writes PASS or FAIL into the
// element of id selftest (docs/report.md).
(function() {
const loadErrors = [];
// Capturing on window sees the 'error' events of images and videos, which do not bubble.
window.addEventListener('error', (event) => {
  const t = event.target;
  if (t && t !== window && (t.currentSrc || t.src))
    loadErrors.push('failed to load ' + (t.getAttribute('src') || t.currentSrc));
  else
    loadErrors.push('script error: ' + event.message);
}, true);
window.addEventListener('unhandledrejection', (event) => loadErrors.push('script error: ' + event.reason));

const data = JSON.parse(document.getElementById('report-data').textContent);
const main = document.getElementById('main');
const sections = new Map();  // run id -> section element (drawn when first shown)

function el(tag, attributes, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attributes || {})) {
    if (k === 'class')
      e.className = v;
    else if (k === 'text')
      e.textContent = v;
    else if (k.startsWith('on'))
      e.addEventListener(k.slice(2), v);
    else
      e.setAttribute(k, v);
  }
  for (const c of children)
    if (c !== null && c !== undefined) e.append(c);
  return e;
}

function formatted(v, digits) {
  if (typeof v !== 'number' || !isFinite(v)) return String(v);
  if (v !== 0 && (Math.abs(v) >= 1e5 || Math.abs(v) < 1e-4)) return v.toExponential(Math.max(1, digits - 1));
  return Number(v.toPrecision(digits)).toString();
}

// --- tables: sortable, worst to best first, with what the reference's noise cannot rank ---

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

// --- compare: the slider between the reference and a method, and the worst regions ---

function viewer(run, chosen) {
  const methods = run.images.methods;
  const scale = Math.max(1, Math.floor(720 / run.width));
  const frame = el('div', {class: 'viewer' + (scale > 1 ? ' pixelated' : '')});
  frame.style.width = run.width * scale + 'px';
  frame.style.aspectRatio = run.width + ' / ' + run.height;
  const bottom = el('img', {class: 'bottom', alt: 'reference', 'data-src': run.images.reference});
  const top = el('img', {class: 'top', alt: ''});
  const split = el('div', {class: 'split'});
  const rightTag = el('span', {class: 'tag right'});
  frame.append(bottom, top, split, el('span', {class: 'tag left', text: 'reference'}), rightTag);
  run.regions.forEach((r, i) => {
    const box = el('div', {class: 'region'}, el('span', {text: String(i + 1)}));
    Object.assign(box.style, {
      left: 100 * r.x / run.width + '%',
      top: 100 * r.y / run.height + '%',
      width: 100 * r.size / run.width + '%',
      height: 100 * r.size / run.height + '%'
    });
    frame.append(box);
  });
  const slider = el('input', {
    type: 'range',
    class: 'slider',
    min: '0',
    max: '100',
    step: '0.1',
    value: '50',
    'aria-label': 'split between the reference (left) and the method (right)'
  });
  slider.style.width = frame.style.width;
  slider.style.maxWidth = '100%';
  const setSplit = () => {
    top.style.clipPath = 'inset(0 0 0 ' + slider.value + '%)';
    split.style.left = slider.value + '%';
  };
  slider.addEventListener('input', setSplit);
  frame.addEventListener('pointermove', (e) => {
    if (!(e.buttons & 1)) return;
    const box = frame.getBoundingClientRect();
    slider.value = String(Math.min(100, Math.max(0, 100 * (e.clientX - box.left) / box.width)));
    slider.dispatchEvent(new Event('input'));
  });
  const select =
      el('select', {'aria-label': 'method'}, ...methods.map((m) => el('option', {value: m.method, text: m.method})));
  select.value = chosen;
  const errorMap = el('input', {type: 'checkbox'});
  const showRegions = el('input', {type: 'checkbox'});
  showRegions.checked = true;
  const legend = el('p', {class: 'note'});
  // The error maps' colours from 0 to the run's scale: the ramp compare paints them with.
  const ramp =
      el('div', {class: 'ramp'}, el('span', {text: '0'}), el('span', {class: 'bar'}),
         el('span', {text: formatted(run.error_map_scale, 3) + ' and above'}));
  ramp.querySelector('.bar').style.background = run.error_ramp;
  const update = () => {
    const m = methods.find((x) => x.method === select.value);
    const src = errorMap.checked ? m.error : m.image;
    if (top.dataset.src !== src) {
      top.dataset.src = src;
      if (top.hasAttribute('src')) top.src = src;
    }
    top.alt = rightTag.textContent = errorMap.checked ? m.method + ' error map' : m.method;
    legend.textContent = errorMap.checked ?
        'Right of the split: |' + m.method +
            ' \u2212 reference| in false colour, one scale for every method of this run (full colour at ' +
            formatted(run.error_map_scale, 3) + ').' :
        'Left of the split: the reference; right: ' + m.method + '. Drag on the image or the slider to move the split.';
    ramp.hidden = !errorMap.checked;
    frame.closest('section')?.querySelectorAll('.cell').forEach(
        (c) => c.classList.toggle('chosen', c.dataset.column === m.method));
  };
  select.addEventListener('change', update);
  errorMap.addEventListener('change', update);
  showRegions.addEventListener('change', () => frame.classList.toggle('hide-regions', !showRegions.checked));
  setSplit();
  const controls =
      el('div', {class: 'controls'}, el('label', null, 'reference | ', select),
         el('label', null, errorMap, ' error map'), el('label', null, showRegions, ' worst regions'));
  return {nodes: [controls, frame, slider, legend, ramp], update};
}

function regions(run) {
  const box = el('div', {class: 'regions'});
  run.regions.forEach((r, i) => {
    const cells = el('div', {class: 'cells'});
    run.columns.forEach((name, column) => {
      const strip = el('img', {alt: name + ', region ' + (i + 1), 'data-src': r.strip});
      strip.style.marginLeft = -column * (r.cell + r.gap) + 'px';
      const windowBox = el('div', {class: 'window'}, strip);
      windowBox.style.width = windowBox.style.height = r.cell + 'px';
      const cell = el('div', {class: 'cell'}, windowBox, el('div', {class: 'cell-label', text: name}));
      cell.dataset.column = name;
      cells.append(cell);
    });
    box.append(
        el('figure', null, el('figcaption', {
             text: 'Region ' + (i + 1) + ': x ' + r.x + ', y ' + r.y + ', ' + r.size + ' x ' + r.size +
                 ' px, enlarged ' + formatted(r.cell / r.size, 3) + ' times (the largest summed error of all methods)'
           }),
           cells));
  });
  return box;
}

function facts(run) {
  const items = [['scene', run.scene], ['size', run.width + ' x ' + run.height]].concat(run.facts);
  return el('div', {class: 'facts'}, ...items.map(([k, v]) => el('span', null, k + ': ', el('b', {text: v}))));
}

function compareSection(run, section) {
  const best = run.table.rows.slice().sort((a, b) => a.rmse - b.rmse)[0];
  const view = viewer(run, best.method);
  section.append(
      el('h3', {text: 'Metrics'}), rankingNote(run), metricsTable(run), tableNotes(run),
      el('h3', {text: 'Reference and method'}), ...view.nodes);
  if (run.regions.length) section.append(el('h3', {text: 'Worst regions'}), regions(run));
  view.update();
}

function animateSection(run, section) {
  section.append(
      el('h3', {text: 'Metrics over ' + run.frames + ' frames'}), rankingNote(run), metricsTable(run), tableNotes(run));
  section.append(el('h3', {text: 'Videos'}));
  if (!run.videos.length) {
    section.append(
        el('p', {class: 'note', text: 'No MP4s in this output (animate writes PNG frames when ffmpeg is missing).'}));
  } else {
    const scale = Math.max(1, Math.min(2, Math.floor(360 / run.width)));
    const grid = el('div', {class: 'videos'});
    for (const v of run.videos) {
      const video = el('video', {
        'data-src': v.src,
        controls: '',
        loop: '',
        playsinline: '',
        preload: 'none',
        width: String(run.width * scale)
      });
      video.muted = true;
      grid.append(el('figure', null, video, el('figcaption', {text: v.name})));
    }
    const playAll = el('button', {type: 'button', text: 'play all from the first frame'});
    playAll.addEventListener('click', () => grid.querySelectorAll('video').forEach((v) => {
      v.currentTime = 0;
      v.play().catch(() => {});
    }));
    section.append(el('div', {class: 'controls'}, playAll), grid);
  }
  section.append(el('h3', {text: 'Error and flicker'}));
  for (const svg of run.plots) {
    const box = el('div', {class: 'plot-box'});
    box.innerHTML = svg;
    section.append(box);
  }
}

function benchSection(run, section) {
  section.append(el('h3', {text: 'Time per frame (median of ' + run.frames + ' frames)'}), metricsTable(run), el('p', {
                   class: 'legend-note',
                   text: 'Ratios are to ' + run.table.base + '. Grey: ' +
                       'the frame with a shading module that returns nothing, the floor under every method.'
                 }));
  for (const svg of run.plots) {
    const box = el('div', {class: 'plot-box'});
    box.innerHTML = svg;
    section.append(box);
  }
}

function draw(run) {
  const section =
      el('section', {id: 'run/' + run.id},
         el('h2', null, el('span', {class: 'kind ' + run.kind, text: run.kind}), run.id), facts(run));
  if (run.kind === 'compare')
    compareSection(run, section);
  else if (run.kind === 'animate')
    animateSection(run, section);
  else
    benchSection(run, section);
  return section;
}

// --- the overview and navigation ---

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

const list = document.getElementById('run-list');
for (const run of data.runs) {
  const a =
      el('a', {href: '#run/' + run.id}, el('span', {class: 'kind ' + run.kind, text: run.kind}), run.id,
         el('span', {class: 'scene', text: run.scene}));
  a.dataset.id = run.id;
  const li = el('li', null, a);
  li.dataset.search =
      (run.id + ' ' + run.kind + ' ' + run.scene + ' ' + run.table.rows.map((r) => r.method).join(' ')).toLowerCase();
  list.append(li);
}
document.getElementById('filter').addEventListener('input', (e) => {
  const words = e.target.value.toLowerCase().split(/\s+/).filter(Boolean);
  for (const li of list.children) li.hidden = !words.every((w) => li.dataset.search.includes(w));
});
main.append(overview());
window.addEventListener('hashchange', route);

// --- the self-test: index.html#selftest ---

function settled(e) {
  const done = () => (e.tagName === 'IMG' ? e.complete : e.readyState >= 1 || e.error !== null);
  if (done()) return Promise.resolve();
  return new Promise((resolve) => {
    const timer = setTimeout(resolve, 20000);
    const finish = () => {
      clearTimeout(timer);
      resolve();
    };
    for (const name of ['load', 'loadedmetadata', 'error']) e.addEventListener(name, finish, {once: true});
  });
}

const h264 = () => document.createElement('video').canPlayType('video/mp4; codecs="avc1.64001E"') !== '';

async function selftest() {
  const out = el('pre', {id: 'selftest', text: 'RUNNING'});
  document.body.append(out);
  const problems = [], limitations = [];
  let images = 0, videos = 0, sliders = 0, labels = 0;
  for (const run of data.runs) {
    const section = show(run.id);
    const media = [...section.querySelectorAll('img, video')];
    await Promise.all(media.map(settled));
    for (const img of section.querySelectorAll('img')) {
      if (img.complete && img.naturalWidth > 0)
        images++;
      else
        problems.push(run.id + ': image ' + img.getAttribute('src') + ' did not load');
    }
    for (const video of section.querySelectorAll('video')) {
      if (video.readyState >= 1)
        videos++;
      else if (video.error && video.error.code === 4 && !h264())
        limitations.push(run.id + ': ' + video.getAttribute('src') + ' not played: this browser has no H.264 decoder');
      else
        problems.push(
            run.id + ': video ' + video.getAttribute('src') + ' did not load' +
            (video.error ? ' (error ' + video.error.code + ')' : ''));
    }
    // Every method's image and error map through the viewer's own controls.
    const select = section.querySelector('.controls select');
    const errorMap = section.querySelector('.controls input[type=checkbox]');
    if (select) {
      const top = section.querySelector('.viewer img.top');
      for (const option of select.options) {
        for (const error of [false, true]) {
          select.value = option.value;
          errorMap.checked = error;
          select.dispatchEvent(new Event('change'));
          await settled(top);
          if (top.complete && top.naturalWidth > 0)
            images++;
          else
            problems.push(run.id + ': image ' + top.getAttribute('src') + ' did not load');
        }
      }
      errorMap.checked = false;
      select.dispatchEvent(new Event('change'));
    }
    const slider = section.querySelector('input.slider');
    if (slider) {
      const top = section.querySelector('.viewer img.top');
      const before = top.style.clipPath;
      slider.value = '25';
      slider.dispatchEvent(new Event('input'));
      const moved = top.style.clipPath;
      if (moved === before || !moved.includes('25%') || getComputedStyle(top).clipPath === 'none')
        problems.push(run.id + ': the slider did not move the clip of the top image (' + before + ' -> ' + moved + ')');
      else
        sliders++;
    }
    if (run.kind === 'compare') {
      const expected = run.regions.length * run.columns.length;
      const found = [...section.querySelectorAll('.cell-label')].map((e) => e.textContent);
      const right = found.length === expected && found.every((t, i) => t === run.columns[i % run.columns.length]);
      if (right)
        labels += found.length;
      else
        problems.push(
            run.id + ': ' + found.length + ' crop labels, ' + expected + ' expected, in the order of the strips');
    }
  }
  const firstCompare = data.runs.find((r) => r.kind === 'compare');
  show(firstCompare ? firstCompare.id : null);  // what a screenshot taken after the test shows
  problems.push(...loadErrors);
  out.textContent = (problems.length ? 'FAIL' : 'PASS') + ' runs=' + data.runs.length + ' images=' + images +
      ' videos=' + videos + ' sliders=' + sliders + ' crop-labels=' + labels +
      (limitations.length ? '\nLIMITATION ' + limitations.join('\nLIMITATION ') : '') +
      (problems.length ? '\n' + problems.join('\n') : '');
}

if (location.hash === '#selftest')
  selftest().catch((e) => {
    const out = document.getElementById('selftest') || document.body.appendChild(el('pre', {id: 'selftest'}));
    out.textContent = 'FAIL self-test stopped: ' + e;
  });
else
  route();
})();
