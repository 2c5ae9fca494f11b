// Live page of `sreh-twin serve` (issues 18, 39): a commissioning tool. Per
// port the state, LED band and the faults being injected; a position dial;
// position/setpoint, speed, tracking error and torque over time; the process
// data buttons a PLC would drive; a parameter editor in engineering units
// (GET /v1/parameters) that shows a refusal's IO-Link error in words; an
// event log with each code's name and the manual's remedy. One event stream
// for every port (/v1/events; per-port streams where the server has none).
// No external resources.
'use strict';

const LED_RGB = { off: '#333', green: '#1ae633', yellow: '#f2d91a', blue: '#2659ff', red: '#ff1a14',
                  orange: '#ff800d', white: '#f2f2f2', violet: '#9933e6' };
const KEEP_S = 10;      // seconds of history in the plots
const LOG_ROWS = 100;   // event log entries kept per port
const LATE_HINT = 0.01; // fraction of late cycles from which the page names the fix

function token() { return document.getElementById('token').value.trim(); }

// An API call; a refusal throws an Error whose text names the IO-Link code
// and its name ("0x8030 Parameter value out of range") or the server's reason.
async function api(method, path, body) {
  const headers = { 'Content-Type': 'application/json' };
  if (token()) headers.Authorization = 'Bearer ' + token();
  const res = await fetch(path, { method, headers, body: body === undefined ? undefined : JSON.stringify(body) });
  const json = await res.json();
  if (!res.ok) {
    const e = new Error(json.iolink_error ? `${json.iolink_error} ${json.message}` : json.error);
    e.iolink = json.iolink_error;
    throw e;
  }
  return json;
}

function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k.startsWith('on')) e.addEventListener(k.slice(2), v); else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c);
  return e;
}

// A number for display: fixed digits, and never "-0" (issue 29).
function num(v, digits) {
  const s = v.toFixed(digits);
  return Number(s) === 0 ? (0).toFixed(digits) : s;
}

// A value in engineering units with as many digits as one raw step needs.
function shown(raw, scale) {
  const digits = scale >= 1 ? 0 : Math.min(6, Math.ceil(-Math.log10(scale) - 1e-9));
  return num(raw * scale, digits);
}

// The position dial (issue 29: with its scale): process-data degrees, 0 at
// the top, positive clockwise as SVG rotates; a tick every 30 deg, labels
// every 90; the actual position solid, the setpoint dashed.
function dial() {
  const ns = 'http://www.w3.org/2000/svg';
  const svg = document.createElementNS(ns, 'svg');
  svg.setAttribute('viewBox', '-84 -70 168 152');
  svg.setAttribute('width', '190');
  svg.setAttribute('height', '185');
  let scale = '';
  for (let a = 0; a < 360; a += 30) {
    const r0 = a % 90 === 0 ? 44 : 48;
    scale += `<line x1="0" y1="-${r0}" x2="0" y2="-52" stroke="#6b7280" stroke-width="1.5" transform="rotate(${a})"/>`;
  }
  for (const [a, x, y, anchor] of [[0, 0, -56, 'middle'], [90, 57, 4, 'start'], [180, 0, 66, 'middle'], [270, -57, 4, 'end']]) {
    scale += `<text x="${x}" y="${y}" font-size="10" text-anchor="${anchor}" fill="#374151">${a}\u00b0</text>`;
  }
  svg.innerHTML = '<circle r="52" fill="#e5e7eb" stroke="#6b7280" stroke-width="2"/>' + scale +
    '<line class="target" x1="0" y1="0" x2="0" y2="-50" stroke="#16a34a" stroke-width="3" stroke-dasharray="4 3"/>' +
    '<line class="actual" x1="0" y1="0" x2="0" y2="-46" stroke="#1f2937" stroke-width="4" stroke-linecap="round"/>' +
    '<circle r="4" fill="#1f2937"/>' +
    '<line x1="-62" y1="76" x2="-48" y2="76" stroke="#1f2937" stroke-width="4"/>' +
    '<text x="-44" y="79" font-size="9" fill="#374151">position</text>' +
    '<line x1="4" y1="76" x2="18" y2="76" stroke="#16a34a" stroke-width="3" stroke-dasharray="4 3"/>' +
    '<text x="22" y="79" font-size="9" fill="#374151">setpoint</text>';
  return svg;
}

// The y range of a plot: the data's (every series), padded, and at least
// +-`min_half` about its middle, so that a flat trace (holding, 0 N m) still
// has ticks (issue 29).
function range(rows, min_half) {
  let lo = Infinity, hi = -Infinity;
  for (const r of rows) for (let i = 1; i < r.length; ++i) { lo = Math.min(lo, r[i]); hi = Math.max(hi, r[i]); }
  if (!isFinite(lo)) return [-1.2 * min_half, 1.2 * min_half];
  const mid = (lo + hi) / 2, half = 1.2 * Math.max(min_half, 0.5 * (hi - lo));
  return [mid - half, mid + half];
}

// The plots of a port: title with unit and legend above each (HTML, outside
// the canvas) instead of a rotated y-axis title, which sat on the tick
// labels (issue 39: "deg-0.005"); the time axis titled below its ticks.
const PLOTS = [
  { key: 'pos', title: 'position and setpoint / deg', labels: ['position', 'setpoint'], colors: ['#1f2937', '#16a34a'],
    min_half: 1, of: (s) => [s.position_deg, s.setpoint_deg] },
  { key: 'speed', title: 'speed / (deg/s)', labels: ['speed'], colors: ['#7c3aed'], min_half: 1, of: (s) => [s.velocity_dps] },
  { key: 'err', title: 'tracking error / deg', labels: ['tracking error'], colors: ['#dc2626'], min_half: 0.01,
    of: (s) => [s.tracking_error_deg] },
  { key: 'torque', title: 'torque / N m', labels: ['torque'], colors: ['#2563eb'], min_half: 0.05, of: (s) => [s.torque_Nm] },
];

// The faults being injected, in words (issue 39): from the port's
// `fault_injection` list where the server sends one, else from its faults.
function injectedFaults(f, baseline) {
  const out = [];
  if (f.flange_blocked) out.push('flange blocked');
  if (!f.link_up) out.push('IO-Link connection down');
  if (f.external_torque_Nm) out.push(`external torque ${f.external_torque_Nm} N m`);
  if (baseline && f.supply_V !== baseline.supply_V) out.push(`supply ${f.supply_V} V (was ${baseline.supply_V} V)`);
  if (baseline && f.ambient_C !== baseline.ambient_C) out.push(`ambient ${f.ambient_C} \u00b0C (was ${baseline.ambient_C} \u00b0C)`);
  return out;
}

function faultText(item) {
  if (typeof item === 'string') return item;
  return item.description || item.name || item.fault || JSON.stringify(item);
}

class PortView {
  constructor(info) {
    this.p = info.port;
    this.data = Object.fromEntries(PLOTS.map((d) => [d.key, []]));
    this.pendingMove = false;
    this.state = info.state;
    const id = (s) => `p${this.p}-${s}`;
    this.id = id;
    this.led = el('span', { class: 'led' });
    this.stateText = el('span', { id: id('state') }, info.state);
    this.injected = el('div', { class: 'injected', id: id('injected'), hidden: '' });
    this.writeError = el('div', { class: 'write-error', id: id('state-write-error'), hidden: '' });
    this.active = el('div', { class: 'active', id: id('active') });
    this.dial = dial();
    this.facts = el('div', { class: 'facts' });
    this.errBox = el('div', { class: 'error', id: id('error') });
    const charts = el('div', { class: 'charts' });
    const chartDivs = PLOTS.map((d) => {
      const legend = el('div', { class: 'chart-legend' });
      const chart = el('div', { class: 'chart', id: id('chart-' + d.key) });
      charts.append(el('div', { class: 'chart-title' }, d.title), legend, chart);
      return [d, chart, legend];
    });
    this.target = el('input', { id: id('target'), type: 'number', value: '90', step: '0.1' });
    this.pset = el('input', { id: id('pset'), type: 'number', value: '1', min: '0', max: '7' });
    this.torqueIn = el('input', { id: id('ext-torque'), type: 'number', value: '0.3', step: '0.05' });
    this.supplyIn = el('input', { id: id('supply'), type: 'number', value: '17', step: '0.5' });
    this.ambientIn = el('input', { id: id('ambient'), type: 'number', value: '60', step: '1' });
    const btn = (name, label, fn) => el('button', { id: id(name), onclick: () => this.run(fn) }, label);
    const controls = el('div', { class: 'controls' },
      el('fieldset', {}, el('legend', {}, 'Process data out'),
        btn('motor-on', 'Motor on', () => this.pd({ motor_on: true })),
        btn('motor-off', 'Motor off', () => this.pd({ motor_on: false, move: false })),
        el('span', { class: 'setting' }, ' target ', this.target, ' deg, set ', this.pset, ' ', btn('move', 'Move', () => this.move())),
        btn('stop', 'Stop', () => this.pd({ stop: true, move: false })),
        btn('release-stop', 'Release stop', () => this.pd({ stop: false })),
        btn('reset', 'Reset error', () => this.pulse('reset_error'))),
      el('fieldset', {}, el('legend', {}, 'Inject faults'),
        btn('link-down', 'Link down', () => this.fault({ link_up: false })),
        btn('link-up', 'Link up', () => this.fault({ link_up: true })),
        btn('block', 'Block flange', () => this.fault({ flange_blocked: true })),
        btn('unblock', 'Free flange', () => this.fault({ flange_blocked: false })),
        btn('power-cycle', 'Power cycle', () => this.fault({ power_cycle: true })), el('br'),
        // Each value with its name, unit and the button that applies it, kept together (issue 29).
        el('span', { class: 'setting' }, 'External torque ', this.torqueIn, ' N m ',
          btn('torque', 'Apply', () => this.fault({ external_torque_Nm: Number(this.torqueIn.value) }))),
        el('span', { class: 'setting' }, 'Supply ', this.supplyIn, ' V ',
          btn('supply-btn', 'Apply', () => this.fault({ supply_V: Number(this.supplyIn.value) }))),
        el('span', { class: 'setting' }, 'Ambient ', this.ambientIn, ' \u00b0C ',
          btn('ambient-btn', 'Apply', () => this.fault({ ambient_C: Number(this.ambientIn.value) })))));
    this.editor = new ParameterEditor(this);
    this.log = el('tbody', { id: id('log') });
    const logBox = el('details', { class: 'log', open: '' }, el('summary', {}, 'Events (newest first)'),
      el('div', { class: 'scroll' }, el('table', {},
        el('thead', {}, el('tr', {}, el('th', {}, 't / s'), el('th', { class: 'l' }, 'code'), el('th', { class: 'l' }, ''),
          el('th', { class: 'l' }, 'name'), el('th', { class: 'l' }, 'remedy (manual chapter 7)'))), this.log)));
    this.root = el('section', { class: 'port', id: id('card') },
      el('h2', {}, this.led, `Port ${this.p}: ${info.device}`, ' \u2014 ', this.stateText),
      this.injected, this.writeError, this.active,
      el('div', { class: 'row' }, el('div', { class: 'side' }, this.dial, this.facts), charts),
      controls, this.errBox, this.editor.root, logBox);
    document.getElementById('ports').append(this.root);
    this.plots = {}; // drawn once the card is laid out: dygraphs measures its box
    for (const [d, chart, legend] of chartDivs) {
      this.plots[d.key] = new Dygraph(chart, [[0, ...d.labels.map(() => 0)]], {
        labels: ['t / s', ...d.labels], colors: d.colors, legend: 'always', labelsDiv: legend, axisLabelFontSize: 11,
        xlabel: 't / s', xLabelHeight: 16,
        strokeWidth: 1.5, xAxisHeight: 20,
        axes: { x: { pixelsPerLabel: 60 },
                y: { axisLabelWidth: 56, pixelsPerLabel: 16, axisLabelFormatter: (v) => String(Number(v.toPrecision(3))) } } });
    }
    this.activeEvents = new Map(); // code -> label, while it is pending
    this.onSummary(info);
    this.refreshFaults();
  }

  async run(fn) {
    try { this.errBox.textContent = ''; await fn(); } catch (e) { this.errBox.textContent = e.message; }
  }
  pd(fields) { return api('PUT', `/v1/ports/${this.p}/processdata/out`, fields); }
  async fault(body) { this.showFaults(await api('POST', `/v1/ports/${this.p}/faults`, body)); }
  async pulse(field) { await this.pd({ [field]: true }); setTimeout(() => this.run(() => this.pd({ [field]: false })), 100); }
  // Handshake as a PLC does it (manual 3.2): Move stays set until Done (T5),
  // then is released (T7); releasing it while Busy would be an error (7.2).
  async move() {
    this.pendingMove = true; // before the PUT: its Done may arrive before the answer does
    try {
      await this.pd({ target_deg: Number(this.target.value), parameter_set: Number(this.pset.value), move: true });
    } catch (e) {
      this.pendingMove = false;
      throw e;
    }
    this.releaseMoveIfDone();
  }

  releaseMoveIfDone() {
    if (this.pendingMove && this.state !== 'Ready' && this.state !== 'Busy') {
      this.pendingMove = false;
      this.run(() => this.pd({ move: false }));
    }
  }

  setLed(name) { this.led.style.background = LED_RGB[name] || '#333'; this.led.title = 'LED band: ' + name; }

  // The port summary (hello) and state changes; fields the server may add
  // (state_write_error, fault_injection) are shown when present.
  onSummary(s) {
    this.onState(s);
    if ('state_write_error' in s) {
      this.writeError.hidden = !s.state_write_error;
      this.writeError.textContent = s.state_write_error ? `State folder not written: ${s.state_write_error}` +
        ' \u2014 the module\u2019s memory and position will not survive a restart until this is fixed' : '';
    }
    if (Array.isArray(s.fault_injection)) {
      this.serverFaults = s.fault_injection.map(faultText);
      this.renderInjected();
    }
    if (s.failure) this.errBox.textContent = 'port failed: ' + s.failure;
  }

  onState(s) {
    if (!s.state) return;
    this.state = s.state;
    this.stateText.textContent = s.state;
    this.root.dataset.state = s.state;
    if (s.led) this.setLed(s.led);
    this.releaseMoveIfDone();
  }

  async refreshFaults() {
    try { this.showFaults(await api('GET', `/v1/ports/${this.p}/faults`)); } catch (e) { /* the stream shows trouble */ }
  }

  showFaults(f) {
    if (!this.baseline) this.baseline = { supply_V: f.supply_V, ambient_C: f.ambient_C };
    this.serverFaults = null; // newer than the last summary's fault_injection list
    this.derivedFaults = injectedFaults(f, this.baseline);
    this.renderInjected();
  }

  renderInjected() {
    const list = this.serverFaults || this.derivedFaults || [];
    this.injected.hidden = list.length === 0;
    this.injected.textContent = list.length ? 'Fault injected: ' + list.join('; ') : '';
    this.root.classList.toggle('faulted', list.length > 0);
  }

  onSample(s) {
    const rot = (deg, cls) => this.dial.querySelector(cls).setAttribute('transform', `rotate(${deg % 360})`);
    rot(s.position_deg, '.actual');
    rot(s.setpoint_deg, '.target');
    this.root.dataset.position = s.position_deg.toFixed(2);
    this.facts.innerHTML = `position ${num(s.position_deg, 2)} deg<br>setpoint ${num(s.setpoint_deg, 2)} deg<br>` +
      `speed ${num(s.velocity_dps, 0)} deg/s<br>torque ${num(s.torque_Nm, 3)} N m<br>` +
      `supply ${num(s.supply_V, 1)} V<br>temperature ${num(s.temperature_C, 1)} \u00b0C<br>t ${num(s.t_s, 2)} s`;
    for (const d of PLOTS) {
      const rows = this.data[d.key];
      rows.push([s.t_s, ...d.of(s)]);
      while (rows.length > 2 && rows[0][0] < s.t_s - KEEP_S) rows.shift();
    }
    if (!this.redrawQueued) { // at most one redraw per animation frame
      this.redrawQueued = true;
      requestAnimationFrame(() => {
        this.redrawQueued = false;
        for (const d of PLOTS) this.plots[d.key].updateOptions({ file: this.data[d.key], valueRange: range(this.data[d.key], d.min_half) });
      });
    }
  }

  // One row of the event log: time, code, appears/disappears, name, remedy.
  logRow(t_s, code, mode, name, remedy, cls) {
    const row = el('tr', { class: cls || '' }, el('td', {}, num(t_s, 2)), el('td', { class: 'l code' }, code),
      el('td', { class: 'l' }, mode), el('td', { class: 'l name' }, name), el('td', { class: 'l remedy' }, remedy || ''));
    this.log.prepend(row);
    while (this.log.rows.length > LOG_ROWS) this.log.deleteRow(-1);
  }

  onDeviceEvent(d) {
    const label = d.label || `event ${d.code}`;
    this.logRow(d.t_s, d.code, d.mode, label, d.remedy, d.mode === 'appears' ? 'appears' : 'disappears');
    if (d.mode === 'appears') this.activeEvents.set(d.code, label); else this.activeEvents.delete(d.code);
    const active = [...this.activeEvents.values()];
    this.active.textContent = active.length ? 'Active: ' + active.join('; ') : '';
  }

  onFailure(d) {
    this.errBox.textContent = 'port failed: ' + d.message;
    this.logRow(d.t_s, '', 'failure', 'the simulation of this port failed', d.message, 'appears');
  }

  onDataStorage(d) { // a replacement module got the master's backup (manual 8)
    const text = `data storage: ${d.action}` + (d.iolink_error ? ` refused ${d.iolink_error}` : '');
    this.logRow(d.t_s, d.iolink_error || '', 'data storage', text, d.iolink_error ? 'See docs/errors.md for the code.' : '');
    this.refreshFaults();
  }
}

// The parameter editor of a port (issue 39): the rows of one group of the
// parameter table (GET /v1/parameters) with name, unit, range, factory
// default and the value the module holds now; a write takes engineering
// units (900 deg/s, not 9000) and shows a refusal's IO-Link error in words.
class ParameterEditor {
  constructor(view) {
    this.view = view;
    const id = view.id;
    this.group = el('select', { id: id('param-group'), onchange: () => this.show() });
    this.body = el('tbody', { id: id('params') });
    this.status = el('div', { class: 'param-status', id: id('param-status') });
    this.root = el('details', { class: 'editor', open: '' }, el('summary', {}, 'Parameters (manual chapter 6)'),
      el('div', { class: 'editor-bar' }, 'Group ', this.group, ' ',
        el('button', { id: id('param-read'), onclick: () => this.readAll() }, 'Read values')),
      el('div', { class: 'scroll' }, el('table', {},
        el('thead', {}, el('tr', {}, el('th', { class: 'l' }, 'parameter'), el('th', { class: 'l' }, 'index'),
          el('th', {}, 'now'), el('th', { class: 'l' }, 'unit'), el('th', {}, 'range'), el('th', {}, 'default'),
          el('th', { class: 'l' }, 'write'))), this.body)),
      this.status,
      el('div', { class: 'note' }, 'Motion sets and settings are kept in the module\u2019s non-volatile memory as ' +
        'soon as they are written (manual 6): the value now is the stored one.'));
    ParameterEditor.catalog().then((rows) => this.fill(rows)).catch((e) => { this.status.textContent = e.message; });
  }

  static catalog() {
    if (!ParameterEditor.rows) ParameterEditor.rows = api('GET', '/v1/parameters');
    return ParameterEditor.rows;
  }

  fill(rows) {
    this.rows = rows;
    const groups = [];
    for (const r of rows) {
      const g = r.record || 'Settings and diagnostics';
      if (!groups.includes(g)) groups.push(g);
    }
    for (const g of groups) this.group.append(el('option', { value: g }, g));
    this.group.value = groups.includes('Motion parameter set 1') ? 'Motion parameter set 1' : groups[0];
    this.show();
  }

  show() {
    const g = this.group.value;
    const id = this.view.id;
    this.body.replaceChildren();
    this.now = new Map(); // row -> its "now" cell (the catalog's rows are shared by every port)
    this.shown = this.rows.filter((r) => (r.record || 'Settings and diagnostics') === g);
    for (const r of this.shown) {
      const key = `${r.index}-${r.subindex}`;
      const now = el('td', { id: id(`param-${key}-now`) }, '\u2026');
      const input = el('input', { id: id(`param-${key}-in`), type: 'number', step: String(r.scale) });
      const write = r.access === 'r' ? el('td', { class: 'l note' }, 'read-only') :
        el('td', { class: 'l' }, input, ' ', el('button', { id: id(`param-${key}-write`),
          onclick: () => this.write(r, input, now) }, 'Write'));
      this.now.set(r, now);
      const title = r.notes ? `${r.notes} (manual ${r.section})` : `manual ${r.section}`;
      this.body.append(el('tr', { title },
        el('td', { class: 'l' }, r.name), el('td', { class: 'l' }, `${r.index}.${r.subindex}`), now,
        el('td', { class: 'l' }, r.unit), el('td', {}, `${shown(r.min, r.scale)} .. ${shown(r.max, r.scale)}`),
        el('td', {}, shown(r.default, r.scale)), write));
    }
    this.readAll();
  }

  async readAll() {
    for (const r of this.shown) {
      const cell = this.now.get(r);
      if (r.access === 'w') { cell.textContent = '\u2014'; continue; }
      try {
        const v = await api('GET', `/v1/ports/${this.view.p}/parameters/${r.index}/${r.subindex}`);
        cell.textContent = typeof v.value === 'number' ? shown(v.value, r.scale) : String(v.value);
      } catch (e) { cell.textContent = e.iolink || '?'; cell.title = e.message; }
    }
  }

  async write(r, input, now) {
    const where = `${r.name} (${r.index}.${r.subindex})`;
    if (input.value.trim() === '' || !isFinite(Number(input.value))) {
      this.status.className = 'param-status refused';
      this.status.textContent = `${where}: give a number in ${r.unit || 'raw units'}`;
      return;
    }
    const value = Number(input.value);
    const raw = Math.round(value / r.scale);
    try {
      await api('PUT', `/v1/ports/${this.view.p}/parameters/${r.index}/${r.subindex}`, { value: raw });
      const back = await api('GET', `/v1/ports/${this.view.p}/parameters/${r.index}/${r.subindex}`);
      now.textContent = shown(back.value, r.scale);
      this.status.className = 'param-status written';
      this.status.textContent = `${where} = ${shown(raw, r.scale)} ${r.unit} written (raw ${raw})`;
    } catch (e) {
      this.status.className = 'param-status refused';
      this.status.textContent = `${where} = ${value} ${r.unit} refused: ${e.message}` +
        ` (range ${shown(r.min, r.scale)} .. ${shown(r.max, r.scale)} ${r.unit}); the module keeps its value`;
    }
  }
}

// The event streams (contract of issues 39 / 40): one /v1/events for every
// port, dispatched by `port`; per-port streams where the server has none. A
// server with /v1/events says so in its port summary (`state_write_error`,
// the same contract), so that an older one is never asked (no 404 logged).
function connect(views, oneStream) {
  const byPort = new Map(views.map((v) => [v.p, v]));
  const status = document.getElementById('status');
  const listen = (es, viewOf) => {
    const on = (type, fn) => es.addEventListener(type, (e) => {
      const d = JSON.parse(e.data);
      const v = viewOf(d);
      if (v) fn(v, d);
    });
    on('hello', (v, d) => v.onSummary(d));
    on('state', (v, d) => v.onSummary(d));
    on('sample', (v, d) => v.onSample(d));
    on('device_event', (v, d) => v.onDeviceEvent(d));
    on('failure', (v, d) => v.onFailure(d));
    on('data_storage', (v, d) => v.onDataStorage(d));
    es.addEventListener('open', () => { status.textContent = 'live'; });
  };
  const perPort = () => {
    for (const v of views) {
      const es = new EventSource(`/v1/ports/${v.p}/events`);
      listen(es, () => v);
      es.onerror = () => { status.textContent = 'reconnecting\u2026'; };
    }
  };
  if (!oneStream) return perPort();
  const one = new EventSource('/v1/events');
  let opened = false;
  one.addEventListener('open', () => { opened = true; });
  listen(one, (d) => byPort.get(d.port));
  one.onerror = () => {
    if (!opened && one.readyState === EventSource.CLOSED) perPort(); // 404: a server without /v1/events
    else status.textContent = 'reconnecting\u2026';
  };
}

async function main() {
  const saved = localStorage.getItem('sreh-token');
  const tokenInput = document.getElementById('token');
  if (saved) tokenInput.value = saved;
  tokenInput.addEventListener('change', () => localStorage.setItem('sreh-token', token()));
  const ports = await api('GET', '/v1/ports');
  const views = ports.map((info) => new PortView(info));
  connect(views, ports.length > 0 && 'state_write_error' in ports[0]);
  showPacing();
  setInterval(showPacing, 2000);
  setInterval(() => views.forEach((v) => v.refreshFaults()), 2000); // faults injected by other clients too
}

// The pacing figures of /v1/stats (issue 27) and, when cycles start late,
// what to do about it (issue 39).
async function showPacing() {
  try {
    const s = await api('GET', '/v1/stats');
    document.getElementById('pacing').textContent =
      `cycle ${(s.cycle_s * 1000).toFixed(1)} ms: jitter p99 ${Math.round(s.jitter_p99_us)} \u00b5s, ` +
      `max ${Math.round(s.jitter_max_us)} \u00b5s, late cycles ${s.late_cycles} of ${s.cycles}`;
    const late = s.cycles > 0 ? s.late_cycles / s.cycles : 0;
    const hint = document.getElementById('pacing-hint');
    hint.hidden = late < LATE_HINT;
    hint.textContent = late < LATE_HINT ? '' :
      `${(100 * late).toFixed(1)} % of the master cycles start late (busy ${Math.round(100 * s.busy_fraction)} %): ` +
      `they catch up in bursts (none is skipped), so a PLC sees an uneven cycle. Fix: restart serve with a longer ` +
      `--master-cycle-ms (e.g. ${Math.max(4, Math.ceil(s.cycle_s * 2000))}), fewer --ports or a lower --speed` +
      (s.realtime_scheduling ? '' : ', or with --rt-priority 50 (needs CAP_SYS_NICE)') +
      '; or stop other work on this machine.';
  } catch (e) { /* the stream's status shows connection trouble */ }
}

main().catch((e) => { document.getElementById('status').textContent = 'error: ' + e.message; });
