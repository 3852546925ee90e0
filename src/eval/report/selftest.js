// index.html#selftest: checks the page as a person would see it and writes PASS or FAIL into the
// element of id selftest (docs/report.md).

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
    // Every method's image and maps through the viewer's own controls.
    const select = section.querySelector('.controls select.method');
    const view = section.querySelector('.controls select.view');
    if (select) {
      const top = section.querySelector('.viewer img.top');
      for (const option of select.options) {
        for (const shown of view.options) {
          select.value = option.value;
          view.value = shown.value;
          select.dispatchEvent(new Event('change'));
          await settled(top);
          if (top.complete && top.naturalWidth > 0)
            images++;
          else
            problems.push(run.id + ': image ' + top.getAttribute('src') + ' did not load');
          const rampShown = section.querySelector('.ramp').offsetParent !== null;
          if (rampShown !== (shown.value !== 'image'))
            problems.push(
                run.id + ': the colour ramp is ' + (rampShown ? 'shown' : 'hidden') + ' with the ' + shown.text);
        }
      }
      view.value = 'image';
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
