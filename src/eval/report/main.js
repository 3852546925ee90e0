// Start: the sidebar, the overview, then the section the URL names, or the self-test.

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

if (location.hash === '#selftest')
  selftest().catch((e) => {
    const out = document.getElementById('selftest') || document.body.appendChild(el('pre', {id: 'selftest'}));
    out.textContent = 'FAIL self-test stopped: ' + e;
  });
else
  route();
