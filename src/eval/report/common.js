'use strict';
// glintlab report's script, in files concatenated in the order report_html.cpp lists them into one
// <script> of index.html: the data glintlab wrote into the page, and the helpers every part uses.

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
