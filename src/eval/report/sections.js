// One run's section: its description, then what its kind (compare, animate, bench, converge) shows.

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

function convergeSection(run, section) {
  section.append(el('h3', {text: 'Error against samples and seconds'}), metricsTable(run), el('p', {
                   class: 'legend-note',
                   text: 'Each backend at rising samples per pixel against ' + run.truth +
                       '; the target is the lowest RMSE every curve reaches (' + run.target_rmse.toPrecision(4) +
                       '), its time interpolated as a power law between the points around it.'
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
  else if (run.kind === 'converge')
    convergeSection(run, section);
  else
    benchSection(run, section);
  return section;
}
