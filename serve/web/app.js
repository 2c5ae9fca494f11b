// Live page of `sreh-twin serve` (issue 18): per port the state, LED band,
// a position dial with the target, tracking error and torque plots from the
// event stream (Server-Sent Events), and buttons that drive the twin through
// the same HTTP API a PLC or HMI would use. No external resources.
'use strict';

const LED_RGB = { off: '#333', green: '#1ae633', yellow: '#f2d91a', blue: '#2659ff', red: '#ff1a14',
                  orange: '#ff800d', white: '#f2f2f2', violet: '#9933e6' };
const KEEP_S = 10; // seconds of history in the plots

function token() { return document.getElementById('token').value.trim(); }

async function api(method, path, body) {
  const headers = { 'Content-Type': 'application/json' };
  if (token()) headers.Authorization = 'Bearer ' + token();
  const res = await fetch(path, { method, headers, body: body === undefined ? undefined : JSON.stringify(body) });
  const json = await res.json();
  if (!res.ok) throw new Error(json.iolink_error ? json.iolink_error + ' ' + json.message : json.error);
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

// The y range of a plot: the data's, padded, and at least +-`min_half` about
// its middle, so that a flat trace (holding, 0 N m) still has ticks (issue 29).
function range(rows, min_half) {
  let lo = Infinity, hi = -Infinity;
  for (const r of rows) { lo = Math.min(lo, r[1]); hi = Math.max(hi, r[1]); }
  if (!isFinite(lo)) return [-1.2 * min_half, 1.2 * min_half];
  const mid = (lo + hi) / 2, half = 1.2 * Math.max(min_half, 0.5 * (hi - lo));
  return [mid - half, mid + half];
}

class PortView {
  constructor(info) {
    this.p = info.port;
    this.data = { err: [], torque: [] };
    this.pendingMove = false;
    this.state = info.state;
    const id = (s) => `p${this.p}-${s}`;
    this.led = el('span', { class: 'led' });
    this.stateText = el('span', { id: id('state') }, info.state);
    this.dial = dial();
    this.facts = el('div', { class: 'facts' });
    this.errBox = el('div', { class: 'error', id: id('error') });
    // Each chart's legend above it, outside the data (issue 29).
    const errLegend = el('div', { class: 'chart-legend' });
    const torqueLegend = el('div', { class: 'chart-legend' });
    const errChart = el('div', { class: 'chart' });
    const torqueChart = el('div', { class: 'chart' });
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
        ' target ', this.target, ' deg, set ', this.pset,
        btn('move', 'Move', () => this.move()),
        btn('stop', 'Stop', () => this.pd({ stop: true, move: false })),
        btn('release-stop', 'Release stop', () => this.pd({ stop: false })),
        btn('reset', 'Reset error', () => this.pulse('reset_error'))),
      el('fieldset', {}, el('legend', {}, 'Faults'),
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
    this.root = el('section', { class: 'port', id: id('card') },
      el('h2', {}, this.led, `Port ${this.p}: ${info.device}`, ' \u2014 ', this.stateText),
      el('div', { class: 'row' }, el('div', {}, this.dial, this.facts), el('div', {}, errLegend, errChart, torqueLegend, torqueChart)),
      controls, this.errBox);
    document.getElementById('ports').append(this.root);
    const opts = (label, unit, color, legend) => ({ labels: ['t_s', label], colors: [color], legend: 'always', labelsDiv: legend,
                                      ylabel: unit, xlabel: 't / s', axisLabelFontSize: 11, strokeWidth: 1.5,
                                      axes: { y: { axisLabelWidth: 50, pixelsPerLabel: 14,
                                                   axisLabelFormatter: (v) => String(Number(v.toPrecision(3))) } } });
    this.errPlot = new Dygraph(errChart, [[0, 0]], opts('tracking error / deg', 'deg', '#dc2626', errLegend));
    this.torquePlot = new Dygraph(torqueChart, [[0, 0]], opts('torque / N m', 'N m', '#2563eb', torqueLegend));
    this.setLed(info.led);
    this.connect();
  }

  async run(fn) {
    try { this.errBox.textContent = ''; await fn(); } catch (e) { this.errBox.textContent = e.message; }
  }
  pd(fields) { return api('PUT', `/v1/ports/${this.p}/processdata/out`, fields); }
  fault(body) { return api('POST', `/v1/ports/${this.p}/faults`, body); }
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

  onState(s) {
    this.state = s.state;
    this.stateText.textContent = s.state;
    this.root.dataset.state = s.state;
    this.setLed(s.led);
    this.releaseMoveIfDone();
  }

  onSample(s) {
    const rot = (deg, cls) => this.dial.querySelector(cls).setAttribute('transform', `rotate(${deg % 360})`);
    rot(s.position_deg, '.actual');
    rot(s.setpoint_deg, '.target');
    this.root.dataset.position = s.position_deg.toFixed(2);
    this.facts.innerHTML = `position ${num(s.position_deg, 2)} deg<br>setpoint ${num(s.setpoint_deg, 2)} deg<br>` +
      `speed ${num(s.velocity_dps, 0)} deg/s<br>torque ${num(s.torque_Nm, 3)} N m<br>` +
      `supply ${num(s.supply_V, 1)} V<br>temperature ${num(s.temperature_C, 1)} \u00b0C<br>t ${num(s.t_s, 2)} s`;
    for (const [key, plot, value] of [['err', this.errPlot, s.tracking_error_deg], ['torque', this.torquePlot, s.torque_Nm]]) {
      const d = this.data[key];
      d.push([s.t_s, value]);
      while (d.length > 2 && d[0][0] < s.t_s - KEEP_S) d.shift();
    }
    if (!this.redrawQueued) { // at most one redraw per animation frame
      this.redrawQueued = true;
      requestAnimationFrame(() => {
        this.redrawQueued = false;
        this.errPlot.updateOptions({ file: this.data.err, valueRange: range(this.data.err, 0.01) });
        this.torquePlot.updateOptions({ file: this.data.torque, valueRange: range(this.data.torque, 0.05) });
      });
    }
  }

  connect() {
    const es = new EventSource(`/v1/ports/${this.p}/events`);
    es.addEventListener('hello', (e) => this.onState(JSON.parse(e.data)));
    es.addEventListener('state', (e) => this.onState(JSON.parse(e.data)));
    es.addEventListener('sample', (e) => this.onSample(JSON.parse(e.data)));
    es.addEventListener('device_event', (e) => {
      const d = JSON.parse(e.data);
      this.errBox.textContent = `event ${d.code} ${d.mode} (qualifier ${d.qualifier}) at ${d.t_s.toFixed(2)} s`;
    });
    es.addEventListener('failure', (e) => { this.errBox.textContent = 'port failed: ' + JSON.parse(e.data).message; });
    es.addEventListener('data_storage', (e) => { // a replacement module got the master's backup (manual 8)
      const d = JSON.parse(e.data);
      this.errBox.textContent = `data storage: ${d.action}` + (d.iolink_error ? ` refused ${d.iolink_error}` : '') +
        ` at ${d.t_s.toFixed(2)} s`;
    });
    es.onopen = () => { document.getElementById('status').textContent = 'live'; };
    es.onerror = () => { document.getElementById('status').textContent = 'reconnecting\u2026'; };
  }
}

async function main() {
  const saved = localStorage.getItem('sreh-token');
  const tokenInput = document.getElementById('token');
  if (saved) tokenInput.value = saved;
  tokenInput.addEventListener('change', () => localStorage.setItem('sreh-token', token()));
  const ports = await api('GET', '/v1/ports');
  ports.forEach((info) => new PortView(info));
  showPacing();
  setInterval(showPacing, 2000);
}

// The pacing figures of /v1/stats (issue 27): p99 jitter and late cycles.
async function showPacing() {
  try {
    const s = await api('GET', '/v1/stats');
    document.getElementById('pacing').textContent =
      `cycle ${(s.cycle_s * 1000).toFixed(1)} ms: jitter p99 ${Math.round(s.jitter_p99_us)} \u00b5s, ` +
      `max ${Math.round(s.jitter_max_us)} \u00b5s, late cycles ${s.late_cycles} of ${s.cycles}`;
  } catch (e) { /* the stream's status shows connection trouble */ }
}

main().catch((e) => { document.getElementById('status').textContent = 'error: ' + e.message; });
