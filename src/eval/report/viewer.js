// compare's images: the slider between the reference and a method, and the labelled worst regions.

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
  const select = el('select', {class: 'method', 'aria-label': 'method'},
                    ...methods.map((m) => el('option', {value: m.method, text: m.method})));
  select.value = chosen;
  // What the right of the split shows: the method's picture, |method - reference| in false colour,
  // or compare's per-pixel LDR-FLIP (runs that measured FLIP), both on the one ramp below.
  const views = [{value: 'image', text: 'image'}, {value: 'error', text: 'error map'}];
  if (methods.every((m) => m.flip)) views.push({value: 'flip', text: 'FLIP map'});
  const view = el('select', {class: 'view', 'aria-label': 'what the right side shows'},
                  ...views.map((v) => el('option', v)));
  const showRegions = el('input', {type: 'checkbox'});
  showRegions.checked = true;
  const legend = el('p', {class: 'note'});
  // The maps' colours from 0 to their scale: the ramp compare paints them with.
  const rampTop = el('span');
  const ramp = el('div', {class: 'ramp'}, el('span', {text: '0'}), el('span', {class: 'bar'}), rampTop);
  ramp.querySelector('.bar').style.background = run.error_ramp;
  const legends = {
    image: (m) => 'Left of the split: the reference; right: ' + m.method +
        '. Drag on the image or the slider to move the split.',
    error: (m) => 'Right of the split: |' + m.method +
        ' \u2212 reference| in false colour, one scale for every method of this run (full colour at ' +
        formatted(run.error_map_scale, 3) + ').',
    flip: (m) => 'Right of the split: LDR-FLIP of ' + m.method +
        ' against the reference per pixel (the displayed pictures; 0 identical, 1 the largest difference).'
  };
  const update = () => {
    const m = methods.find((x) => x.method === select.value);
    const src = {image: m.image, error: m.error, flip: m.flip}[view.value];
    if (top.dataset.src !== src) {
      top.dataset.src = src;
      if (top.hasAttribute('src')) top.src = src;
    }
    top.alt = rightTag.textContent = view.value === 'image' ? m.method : m.method + ' ' + view.selectedOptions[0].text;
    legend.textContent = legends[view.value](m);
    rampTop.textContent = view.value === 'flip' ? '1' : formatted(run.error_map_scale, 3) + ' and above';
    ramp.hidden = view.value === 'image';
    frame.closest('section')?.querySelectorAll('.cell').forEach(
        (c) => c.classList.toggle('chosen', c.dataset.column === m.method));
  };
  select.addEventListener('change', update);
  view.addEventListener('change', update);
  showRegions.addEventListener('change', () => frame.classList.toggle('hide-regions', !showRegions.checked));
  setSplit();
  const controls =
      el('div', {class: 'controls'}, el('label', null, 'reference | ', select),
         el('label', null, 'show ', view), el('label', null, showRegions, ' worst regions'));
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
