// sreh-twin studio (issue 37): the page keeps one state (the project, as
// studio/project.hpp describes it) and the pinned options; every edit
// updates the address (#state) and, debounced, asks /api/answer. The server
// does all sizing; this script only shows what it answers.
(() => {
  'use strict';
  const META = window.STUDIO.meta;
  const DEBOUNCE_MS = 150;
  const MAX_PINS = 4;
  const $ = (id) => document.getElementById(id);
  const esc = (s) => String(s).replace(/[&<>"']/g, (c) => ({'&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;'}[c]));
  const fmt = (v, d) => (v === null || v === undefined ? '-' : Number(v).toFixed(d));
  const shapeKeys = (shape) => META.shapes.find((s) => s.shape === shape).keys;
  const DEFAULT_DIMS = {mass_kg: 0.1, radius_m: 0.03, thickness_m: 0.01, inner_radius_m: 0.01, outer_radius_m: 0.03,
                        x_m: 0.02, y_m: 0.02, z_m: 0.02, length_m: 0.03, scale: 0.001};

  let state = window.STUDIO.project;
  let pins = []; // [{state, answer}]
  let seq = 0;
  let timer = null;
  const timings = []; // request -> answer shown, ms (docs/performance-sizing.md)
  window.studio = {timings, get state() { return state; }, get pins() { return pins; }, answer: null, pending: 0, uploads: []};

  function fromHash() {
    const m = location.hash.match(/^#state=(.*)$/);
    if (!m) return;
    try {
      const h = JSON.parse(decodeURIComponent(m[1]));
      // Keys the link leaves out (an older link, a hand-made one) keep the project's.
      if (h.state) state = Object.assign(JSON.parse(JSON.stringify(window.STUDIO.project)), h.state);
      for (const p of state.parts) {
        if (p.payload === undefined) p.payload = false;
        for (const key of ['at_m', 'rpy_deg']) if (!Array.isArray(p[key])) p[key] = [0, 0, 0];
      }
      if (Array.isArray(h.pins)) pins = h.pins.slice(0, MAX_PINS).map((s) => ({state: s, answer: null}));
    } catch (e) { /* a broken link: keep the project */ }
  }

  function link() {
    return '#state=' + encodeURIComponent(JSON.stringify({state, pins: pins.map((p) => p.state)}));
  }

  // --- inputs -------------------------------------------------------------
  function partHtml(p, k) {
    const opts = META.shapes.map((s) => `<option${s.shape === p.shape ? ' selected' : ''}>${s.shape}</option>`).join('');
    const dims = shapeKeys(p.shape).map((key) =>
      `<label>${key} <input id="part-${k}-${key}" data-k="${k}" data-key="${key}" type="number" step="any" value="${p[key]}"></label>`).join('');
    const vec = (key, label) => [0, 1, 2].map((i) =>
      `<label>${label[i]} <input id="part-${k}-${key}-${i}" data-k="${k}" data-key="${key}" data-i="${i}" type="number" step="any" value="${p[key][i]}"></label>`).join('');
    // A mesh part's STL: uploaded to the studio, which stores it with the project (docs/studio.md "STL meshes").
    const stl = p.shape !== 'mesh' ? '' : `<div class="row"><label>STL file (ASCII or binary, closed) <input id="part-${k}-stl" data-stl="${k}" type="file" accept=".stl,.STL"></label>
<span class="note">stored: <span id="part-${k}-file" title="${esc(p.file || '')}">${p.file ? esc(p.file.split('/').pop()) : 'none yet'}</span>; scale 0.001 for a file in mm</span></div>`;
    return `<fieldset class="part" id="part-${k}"><legend>Part ${k + 1}</legend>
<div class="row"><label>name <input id="part-${k}-name" data-k="${k}" data-key="name" type="text" value="${esc(p.name)}"></label>
<label>shape <select id="part-${k}-shape" data-k="${k}" data-key="shape">${opts}</select></label>
<label><input id="part-${k}-payload" data-k="${k}" data-key="payload" type="checkbox"${p.payload ? ' checked' : ''}> payload (gripped in a cycle)</label>
<button type="button" id="part-${k}-remove" data-remove="${k}">remove</button></div>
${stl}<div class="row">${dims}</div>
<div class="row">${vec('at_m', ['at x m', 'y m', 'z m'])}</div>
<div class="row">${vec('rpy_deg', ['roll deg', 'pitch deg', 'yaw deg'])}</div></fieldset>`;
  }

  function segmentHtml(g, i) {
    const rm = `<button type="button" data-seg-remove="${i}">remove</button>`;
    if (g.kind === 'move') {
      return `<li id="seg-${i}">move <label>${g.relative ? 'by' : 'to'} <input id="seg-${i}-deg" data-seg="${i}" data-key="deg" type="number" step="any" value="${g.deg}"> deg</label>` +
        `<label><input id="seg-${i}-relative" data-seg="${i}" data-key="relative" type="checkbox"${g.relative ? ' checked' : ''}> relative</label>${rm}</li>`;
    }
    if (g.kind === 'dwell') {
      return `<li id="seg-${i}">dwell <label><input id="seg-${i}-s" data-seg="${i}" data-key="s" type="number" step="any" min="0" value="${g.s}"> s</label>${rm}</li>`;
    }
    return `<li id="seg-${i}">${g.kind === 'grip' ? 'grip: the payload joins the load' : 'release: the payload leaves the load'}${rm}</li>`;
  }

  function renderInputs() {
    $('name').value = state.name;
    const cycle = state.mode === 'cycle';
    $('mode').value = state.mode;
    $('uncertainty').checked = !!state.uncertainty;
    document.querySelectorAll('label.single').forEach((l) => { l.hidden = cycle; });
    $('cycle-editor').hidden = !cycle;
    $('segments').innerHTML = state.segments.map(segmentHtml).join('');
    $('parts').innerHTML = state.parts.map(partHtml).join('');
    const tilt = state.mounting_tilt_deg;
    $('mounting').value = tilt === 0 ? '0' : tilt === 90 ? '90' : 'tilt';
    $('tilt').value = tilt;
    $('tilt-label').hidden = $('mounting').value !== 'tilt';
    for (const id of ['angle_deg', 'dwell_s', 'tolerance_deg', 'target_ms', 'voltage_V', 'ambient_C']) $(id).value = state[id];
    $('target').value = state.target;
    $('target-ms-label').hidden = cycle || state.target === 'none';
    $('set-mode').value = state.set ? 'given' : 'recommend';
    for (const id of ['speed_dps', 'accel_pct', 'jerk_pct']) $(id).value = state.set ? state.set[id] : '';
    document.querySelectorAll('label.given').forEach((l) => { l.hidden = cycle || !state.set; });
  }

  function num(el) {
    const v = parseFloat(el.value);
    return Number.isFinite(v) ? v : null;
  }

  function onPartInput(e) {
    const el = e.target;
    const k = Number(el.dataset.k);
    const key = el.dataset.key;
    if (Number.isNaN(k) || !key) return;
    const p = state.parts[k];
    if (key === 'name') p.name = el.value;
    else if (key === 'payload') p.payload = el.checked;
    else if (key === 'shape') {
      const old = p;
      const next = {name: old.name, shape: el.value, at_m: old.at_m, rpy_deg: old.rpy_deg, payload: old.payload};
      if (el.value === 'mesh') next.file = old.file || '';
      for (const dim of shapeKeys(el.value)) next[dim] = old[dim] !== undefined ? old[dim] : DEFAULT_DIMS[dim];
      state.parts[k] = next;
      renderInputs();
    } else if (el.dataset.i !== undefined) {
      const v = num(el);
      if (v === null) return;
      p[key][Number(el.dataset.i)] = v;
    } else {
      const v = num(el);
      if (v === null) return;
      p[key] = v;
    }
    changed();
  }

  // Sends the picked STL to the studio; its answer is the stored file, or
  // what is wrong with it (shown in the error line, naming the file).
  async function uploadMesh(k, file) {
    const fail = (why) => { $('error').hidden = false; $('error').textContent = why; window.studio.uploads.push({name: file.name, error: why}); };
    const limit = META.max_mesh_upload_bytes;
    if (file.size > limit) {
      fail(`${file.name}: ${(file.size / 1048576).toFixed(1)} MB, more than the ${limit / 1048576} MB an STL upload may have`);
      return;
    }
    const r = await fetch('/api/mesh?name=' + encodeURIComponent(file.name), {method: 'POST', body: file});
    const j = await r.json().catch(() => ({error: `${file.name}: the studio refused it (HTTP ${r.status})`}));
    if (j.error) { fail(j.error); return; }
    state.parts[k].file = j.file;
    window.studio.uploads.push({name: file.name, file: j.file, triangles: j.triangles});
    renderInputs();
    changed();
  }

  function onSegmentInput(e) {
    const el = e.target;
    const i = Number(el.dataset.seg);
    if (Number.isNaN(i) || !el.dataset.key) return;
    const g = state.segments[i];
    if (el.dataset.key === 'relative') { g.relative = el.checked; renderInputs(); }
    else { const v = num(el); if (v === null) return; g[el.dataset.key] = v; }
    changed();
  }

  function onInput(e) {
    const id = e.target.id;
    if (id === 'name') state.name = e.target.value;
    else if (id === 'mode') { state.mode = e.target.value; renderInputs(); }
    else if (id === 'uncertainty') state.uncertainty = e.target.checked;
    else if (id === 'mounting') {
      if (e.target.value !== 'tilt') state.mounting_tilt_deg = Number(e.target.value);
      $('tilt-label').hidden = e.target.value !== 'tilt';
      $('tilt').value = state.mounting_tilt_deg;
    } else if (id === 'tilt') { const v = num(e.target); if (v === null) return; state.mounting_tilt_deg = v; }
    else if (id === 'target') { state.target = e.target.value; $('target-ms-label').hidden = state.target === 'none'; }
    else if (id === 'set-mode') {
      state.set = e.target.value === 'given' ? {speed_dps: 3000, accel_pct: 100, jerk_pct: 100} : null;
      renderInputs();
    } else if (['speed_dps', 'accel_pct', 'jerk_pct'].includes(id)) {
      const v = num(e.target); if (v === null || !state.set) return; state.set[id] = v;
    } else if (id in state) { const v = num(e.target); if (v === null) return; state[id] = v; }
    else return;
    changed();
  }

  // --- answer -------------------------------------------------------------
  function changed() {
    history.replaceState(null, '', link());
    $('load-picture').hidden = true; // drawn for the load as it was: shown again on request
    exportLinks();
    clearTimeout(timer);
    window.studio.pending = 1;
    $('status').classList.add('busy');
    timer = setTimeout(ask, DEBOUNCE_MS);
  }

  async function post(s) {
    const r = await fetch('/api/answer', {method: 'POST', body: JSON.stringify(s), headers: {'Content-Type': 'application/json'}});
    return r.json();
  }

  // A cycle or the uncertainty band takes seconds: the simulations run so
  // far against about how many such an answer takes (a searched set up to
  // 60, a cycle's back-offs, 32 samples and the robust search's).
  function expectedSimulations(s) {
    let n = s.mode === 'cycle' ? 61 * (s.segments.some((g) => g.kind === 'grip') ? 2 : 1) + 9 : s.target === 'none' ? 2 : 21;
    if (s.uncertainty) n += 2 * 32;
    return n;
  }

  function watchProgress(mine, s) {
    if (s.mode !== 'cycle' && !s.uncertainty) return () => {};
    const expected = expectedSimulations(s);
    $('progress-line').hidden = false;
    $('progress').value = 0;
    $('progress-text').textContent = 'sizing...';
    const poll = setInterval(async () => {
      const p = await (await fetch('/api/progress')).json();
      if (mine !== seq) return;
      $('progress').value = Math.min(95, 100 * p.simulations / expected);
      $('progress-text').textContent = `${p.simulations} simulations run`;
    }, 200);
    return () => { clearInterval(poll); $('progress-line').hidden = true; };
  }

  async function ask() {
    const mine = ++seq;
    const t0 = performance.now();
    const done = watchProgress(mine, state);
    let a;
    try { a = await post(state); } finally { done(); }
    if (mine !== seq) return; // a newer edit is on its way
    const t1 = performance.now(); // the answer read and parsed
    window.studio.answer = a;
    showAnswer(a);
    timings.push({client_ms: performance.now() - t0, server_ms: a.elapsed_ms, cpu_ms: a.cpu_ms, shown_ms: performance.now() - t1});
    $('status').classList.remove('busy');
    $('status').textContent = `answered in ${Math.round(performance.now() - t0)} ms`;
    window.studio.pending = 0;
  }

  function loadFigures(l) {
    if (!l) return '';
    const pct = 100 * l.inertia_gcm2 / l.max_gcm2;
    const cls = pct > 100 ? 'badb' : pct > 85 ? 'warnb' : 'okb';
    let o = `<table><tr><td class="l">mass</td><td id="load-mass">${fmt(l.mass_kg, 3)} kg</td></tr>
<tr><td class="l">inertia about the axis</td><td id="load-inertia">${fmt(l.inertia_gcm2, 1)} g cm^2 of ${l.max_gcm2} (${fmt(pct, 0)} %)</td></tr>
<tr><td class="l">centre of mass</td><td id="load-com">[${l.com_m.map((v) => fmt(1000 * v, 1)).join(', ')}] mm, ${fmt(1000 * l.com_radius_m, 1)} mm from the axis</td></tr>
<tr><td class="l">gravity torque (largest over a turn)</td><td id="load-gravity">${fmt(l.gravity_torque_Nm, 3)} N m</td></tr></table>
<div class="loadbar"><div class="fill ${cls}" style="width:${Math.min(pct, 125) / 1.25}%"></div><div class="mark" style="left:80%"></div></div>`;
    if (l.over_text) o += `<p class="over" id="load-over">${esc(l.over_text)}</p>`;
    if (l.parts.length) {
      o += '<table id="load-parts"><tr><th>#</th><th class="l">part</th><th>mass kg</th><th>inertia g cm^2</th><th>share</th></tr>' +
        l.parts.map((p, k) => `<tr><td>${k + 1}</td><td class="l">${esc(p.name || p.shape)}</td><td>${fmt(p.mass_kg, 3)}</td>` +
          `<td>${fmt(p.inertia_gcm2, 1)}</td><td>${fmt(100 * p.share, 1)} %</td></tr>`).join('') + '</table>';
    }
    return o;
  }

  function cycleSummaryHtml(a) {
    const s = a.summary, j = a.size;
    return `<p class="answerline"><b class="${s.feasible ? 'okt' : 'badt'}" id="answer-verdict">${s.feasible ? 'FEASIBLE' : 'NOT FEASIBLE'}</b>;
binding limit: <b id="answer-binding">${esc(s.binding_limit_words)}</b>; cycle <span id="rec-cycle">${fmt(j.cycle_s, 4)}</span> s</p>
<table id="answer-set"><tr><th class="l">${j.mode === 'recommend' ? 'recommended' : 'given'} set</th><th>speed deg/s</th><th>acceleration %</th><th>jerk %</th><th>load g cm^2</th></tr>` +
      j.sets.map((x, k) => `<tr><td class="l" id="rec-set-${k}">${x.parameter_set}</td><td id="rec-speed-${k}">${x.speed_dps}</td>` +
        `<td id="rec-accel-${k}">${x.accel_pct}</td><td id="rec-jerk-${k}">${x.jerk_pct}</td><td>${fmt(x.load_gcm2, 1)}</td></tr>`).join('') + '</table>';
  }

  function summaryHtml(a) {
    if (a.size.request.cycle_file !== undefined) return cycleSummaryHtml(a);
    const s = a.summary, j = a.size, set = s.set;
    return `<p class="answerline"><b class="${s.feasible ? 'okt' : 'badt'}" id="answer-verdict">${s.feasible ? 'FEASIBLE' : 'NOT FEASIBLE'}</b>;
binding limit: <b id="answer-binding">${esc(s.binding_limit_words)}</b></p>
<table id="answer-set"><tr><th class="l">${j.mode === 'recommend' ? 'recommended' : 'given'} set</th><th>speed deg/s</th><th>acceleration %</th><th>jerk %</th><th>positioning s</th><th>cycle s</th></tr>
<tr><td class="l" id="rec-set">${set.parameter_set}</td><td id="rec-speed">${set.speed_dps}</td><td id="rec-accel">${set.accel_pct}</td>
<td id="rec-jerk">${set.jerk_pct}</td><td id="rec-positioning">${fmt(j.positioning_s, 4)}</td><td id="rec-cycle">${fmt(j.cycle_s, 4)}</td></tr></table>`;
  }

  function wayOutHtml(w) {
    if (!w) return '';
    let o = '<h3>Way out</h3><table class="limits" id="limits"><tr><th class="l">limit</th><th>this option</th><th>allowed</th><th class="l"></th></tr>' +
      w.limits.map((r) => `<tr><td class="l">${esc(r.limit)}</td><td>${esc(r.value)}</td><td>${esc(r.allowed)}</td>` +
        `<td class="l${r.over ? ' overc' : ''}">${esc(r.by)}</td></tr>`).join('') + '</table>';
    const first = w.options.findIndex((x) => x.feasible);
    o += '<ul id="way-options">' + w.options.map((x, i) => `<li id="way-${i}">${i === first ? '<b>nearest feasible:</b> ' : ''}${esc(x.label)}: ` +
      (x.feasible ? `feasible, set ${x.set.speed_dps} deg/s, ${x.set.accel_pct} %, ${x.set.jerk_pct} %; positioning ${fmt(x.positioning_s, 4)} s, cycle ${fmt(x.cycle_s, 4)} s`
                  : `still not feasible (${esc(x.binding_limit)})`) +
      `<button type="button" class="waybtn" data-way="${i}">apply</button></li>`).join('') + '</ul>';
    return o;
  }

  function showAnswer(a) {
    $('load-figures').innerHTML = loadFigures(a.load);
    $('error').hidden = !a.error;
    $('error').textContent = a.error || '';
    $('summary').innerHTML = a.summary ? summaryHtml(a) : '';
    $('verdict-box').innerHTML = a.verdict_html || '';
    $('uncertainty-box').innerHTML = a.uncertainty_html || '';
    $('way-out').innerHTML = wayOutHtml(a.way_out);
    $('writes').innerHTML = !a.summary ? '' : a.writes_ready
      ? `<pre id="writes-text">${esc(a.writes.join('\n'))}</pre><p class="note">scenario steps, ready to paste under <code>steps:</code></p>`
      : '<p id="writes-none" class="over">No writes to paste: this set does not meet what is asked. Apply a way out above.</p>';
    $('plots').innerHTML = a.plots_html || '';
    $('command').textContent = a.command || '';
  }

  // --- compare ------------------------------------------------------------
  const ROWS = [
    ['load', 'load g cm^2', (p) => fmt(p.answer && p.answer.load ? p.answer.load.inertia_gcm2 : null, 1)],
    ['tilt', 'axis tilt deg', (p) => p.state.mounting_tilt_deg],
    ['voltage', 'supply V', (p) => p.state.voltage_V],
    ['ambient', 'ambient degC', (p) => p.state.ambient_C],
    ['move', 'move deg / dwell s', (p) => (p.state.mode === 'cycle' ? `cycle of ${p.state.segments.length} segments` : `${p.state.angle_deg} / ${p.state.dwell_s}`)],
    ['band', 'uncertainty band', (p) => (p.state.uncertainty ? 'on' : 'off')],
    ['target', 'required', (p) => (p.state.target === 'none' ? '-' : `${p.state.target} ${p.state.target_ms} ms`)],
    ['verdict', 'verdict', (p) => (!p.answer ? '...' : p.answer.summary ? (p.answer.summary.feasible ? 'feasible' : 'NOT feasible') : 'error')],
    ['binding', 'binding limit', (p) => (p.answer && p.answer.summary ? p.answer.summary.binding_limit_words : '-')],
    ['set', 'speed / accel / jerk', (p) => (p.answer && p.answer.summary
      ? p.answer.summary.sets.map((x) => `${x.speed_dps} / ${x.accel_pct} / ${x.jerk_pct}`).join('; ') : '-')],
    ['positioning', 'positioning s', (p) => fmt(p.answer && p.answer.size ? p.answer.size.positioning_s : null, 4)],
    ['cycle', 'cycle s', (p) => fmt(p.answer && p.answer.size ? p.answer.size.cycle_s : null, 4)],
    ['peak', 'peak torque %', (p) => fmt(p.answer && p.answer.size ? p.answer.size.utilisation.peak_torque_pct : null, 0)],
    ['rms', 'RMS torque %', (p) => fmt(p.answer && p.answer.size ? p.answer.size.utilisation.rms_torque_pct : null, 0)],
    ['thermal', 'thermal margin K', (p) => fmt(p.answer && p.answer.size ? p.answer.size.utilisation.thermal_margin_K : null, 1)],
  ];

  function renderCompare() {
    if (!pins.length) { $('compare').innerHTML = '<p class="note">No option pinned yet.</p>'; return; }
    let o = '<table class="compare" id="compare-table"><tr><th class="l"></th>' +
      pins.map((p, c) => `<th id="cmp-head-${c}">option ${c + 1} <button type="button" data-unpin="${c}">remove</button></th>`).join('') + '</tr>';
    for (const [key, label, get] of ROWS) {
      const vals = pins.map(get);
      o += `<tr><td class="l">${label}</td>` + vals.map((v, c) =>
        `<td id="cmp-${key}-${c}"${c > 0 && String(v) !== String(vals[0]) ? ' class="diff"' : ''}>${esc(v)}</td>`).join('') + '</tr>';
    }
    $('compare').innerHTML = o + '</table>';
  }

  async function pin() {
    if (pins.length >= MAX_PINS) pins.shift();
    const p = {state: JSON.parse(JSON.stringify(state)), answer: window.studio.answer};
    pins.push(p);
    if (!p.answer || window.studio.pending) p.answer = await post(p.state);
    history.replaceState(null, '', link());
    renderCompare();
  }

  // --- export -------------------------------------------------------------
  function exportLinks() {
    const q = '?s=' + encodeURIComponent(JSON.stringify(state));
    $('export-project').href = '/api/export/project' + q;
    $('export-csv').href = '/api/export/csv' + q;
    $('export-scenario').href = '/api/export/scenario' + q;
    $('export-report').href = '/report' + q;
    $('permalink').href = link();
  }

  // --- wiring -------------------------------------------------------------
  fromHash();
  renderInputs();
  renderCompare();
  exportLinks();
  $('parts').addEventListener('input', (e) => { if (e.target.type !== 'checkbox' && e.target.type !== 'file') onPartInput(e); });
  $('parts').addEventListener('change', (e) => {
    if (e.target.type === 'file') { if (e.target.files.length) uploadMesh(Number(e.target.dataset.stl), e.target.files[0]); }
    else if (e.target.tagName === 'SELECT' || e.target.type === 'checkbox') onPartInput(e);
  });
  // A list's remove buttons: data-remove on a part, data-seg-remove on a segment.
  const removeOnClick = (id, key, list) => $(id).addEventListener('click', (e) => {
    const k = e.target.dataset[key];
    if (k === undefined) return;
    list().splice(Number(k), 1);
    renderInputs();
    changed();
  });
  removeOnClick('parts', 'remove', () => state.parts);
  const elsewhere = (e) => e.target.closest('#parts') || e.target.closest('#segments');
  $('inputs').addEventListener('input', (e) => { if (!elsewhere(e) && e.target.type !== 'checkbox') onInput(e); });
  $('inputs').addEventListener('change', (e) => {
    if ((e.target.tagName === 'SELECT' || e.target.type === 'checkbox') && !elsewhere(e)) onInput(e);
  });
  $('segments').addEventListener('input', (e) => { if (e.target.type !== 'checkbox') onSegmentInput(e); });
  $('segments').addEventListener('change', (e) => { if (e.target.type === 'checkbox') onSegmentInput(e); });
  removeOnClick('segments', 'segRemove', () => state.segments);
  for (const [id, seg] of [['add-move', {kind: 'move', deg: 90, relative: false}], ['add-dwell', {kind: 'dwell', s: 0.2}],
                           ['add-grip', {kind: 'grip'}], ['add-release', {kind: 'release'}]]) {
    $(id).addEventListener('click', () => { state.segments.push(Object.assign({}, seg)); renderInputs(); changed(); });
  }
  $('add-part').addEventListener('click', () => {
    state.parts.push({name: `part ${state.parts.length + 1}`, shape: 'disk', mass_kg: 0.1, radius_m: 0.03, thickness_m: 0.01,
                      at_m: [0, 0, 0.005], rpy_deg: [0, 0, 0], payload: false});
    renderInputs();
    changed();
  });
  $('pin').addEventListener('click', pin);
  $('show-picture').addEventListener('click', () => {
    const img = $('load-picture');
    img.src = '/api/picture?s=' + encodeURIComponent(JSON.stringify(state));
    img.hidden = false;
  });
  $('compare').addEventListener('click', (e) => {
    if (e.target.dataset.unpin === undefined) return;
    pins.splice(Number(e.target.dataset.unpin), 1);
    history.replaceState(null, '', link());
    renderCompare();
  });
  $('way-out').addEventListener('click', (e) => {
    const i = e.target.dataset.way;
    if (i === undefined || !window.studio.answer.way_out) return;
    Object.assign(state, window.studio.answer.way_out.options[Number(i)].patch);
    renderInputs();
    changed();
  });
  // Pins from a link: their answers, one after the other.
  (async () => { for (const p of pins) { p.answer = await post(p.state); renderCompare(); } })();
  changed();
})();
