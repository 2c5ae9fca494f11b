// Layout problems of the page as laid out now (issue 29), as strings:
// - an element of an SVG plot (text, legend, axis, marker) outside the SVG's
//   box, or two of its texts on top of each other (the data drawn inside
//   the clipped group is left out: it is cut at the plot area on purpose);
// - a title, legend, key or axis label of an interactive plot (dygraphs)
//   outside its figure;
// - an axis title of an interactive plot on one of its tick labels;
// - anything wider than the page: the document scrolls sideways, or an
//   element reaches past the viewport (inside a scrolling box is fine).
(() => {
  const bad = [];
  const slack = 1; // rounding of sub-pixel layout
  const name = (e) => {
    const cls = typeof e.className === 'string' ? e.className : (e.className && e.className.baseVal) || '';
    return `${e.tagName.toLowerCase()}${e.id ? '#' + e.id : ''}${cls ? '.' + cls.split(' ').join('.') : ''} "${(e.textContent || '').trim().slice(0, 50)}"`;
  };
  const outside = (r, box) => r.left < box.left - slack || r.right > box.right + slack || r.top < box.top - slack ||
    r.bottom > box.bottom + slack;
  const overlap = (a, b) => Math.min(a.right, b.right) - Math.max(a.left, b.left) > 2 &&
    Math.min(a.bottom, b.bottom) - Math.max(a.top, b.top) > 2;
  for (const svg of document.querySelectorAll('svg.plot, svg')) {
    const box = svg.getBoundingClientRect();
    if (box.width === 0 || box.height === 0) continue; // not shown (an interactive twin replaces it)
    const owner = svg.id || (svg.closest('[id]') ? svg.closest('[id]').id : 'svg');
    const texts = [];
    for (const e of svg.querySelectorAll('text, line, rect, circle, polyline, path')) {
      if (e.closest('defs') || e.closest('[clip-path]')) continue;
      const r = e.getBoundingClientRect();
      if (r.width === 0 && r.height === 0) continue;
      if (outside(r, box)) bad.push(`${owner}: ${name(e)} outside its plot (${Math.round(r.left)}..${Math.round(r.right)} x ` +
                                    `${Math.round(r.top)}..${Math.round(r.bottom)} in ${Math.round(box.left)}..${Math.round(box.right)} x ` +
                                    `${Math.round(box.top)}..${Math.round(box.bottom)})`);
      if (e.tagName.toLowerCase() === 'text') texts.push([e, r]);
    }
    for (let i = 0; i < texts.length; ++i) {
      for (let j = i + 1; j < texts.length; ++j) {
        if (overlap(texts[i][1], texts[j][1])) bad.push(`${owner}: ${name(texts[i][0])} overlaps ${name(texts[j][0])}`);
      }
    }
  }
  for (const fig of document.querySelectorAll('.fig.live, .chart')) { // report figures, the live page's charts
    const box = fig.getBoundingClientRect();
    for (const e of fig.querySelectorAll('.dytitle, .dylegend, .dykey, .dygraph-axis-label, .dygraph-label, .dygraph-legend, canvas')) {
      const r = e.getBoundingClientRect();
      if (r.width === 0 && r.height === 0) continue;
      if (r.left < box.left - slack || r.right > box.right + slack) bad.push(`${fig.id || name(fig)}: ${name(e)} outside its figure`);
      if (e.scrollWidth > e.clientWidth + slack && e.clientWidth > 0 && getComputedStyle(e).overflowX === 'hidden') {
        bad.push(`${fig.id || name(fig)}: ${name(e)} cut (${e.scrollWidth} > ${e.clientWidth})`);
      }
    }
  }
  // An axis title of an interactive plot on a tick label (issue 39: the live
  // page's "deg" ran into "-0.005"): the extents of the texts themselves.
  const textBox = (e) => { const r = document.createRange(); r.selectNodeContents(e); return r.getBoundingClientRect(); };
  for (const fig of document.querySelectorAll('.fig.live, .chart')) {
    const titles = [...fig.querySelectorAll('.dygraph-label')].filter((e) => (e.textContent || '').trim());
    const ticks = [...fig.querySelectorAll('.dygraph-axis-label')].filter((e) => (e.textContent || '').trim());
    for (const t of titles) {
      const tr = textBox(t);
      if (tr.width === 0 && tr.height === 0) continue;
      for (const k of ticks) {
        if (overlap(tr, textBox(k))) bad.push(`${fig.id || name(fig)}: axis title ${name(t)} overlaps tick ${name(k)}`);
      }
    }
  }
  const page = document.documentElement;
  if (page.scrollWidth > page.clientWidth + slack) bad.push(`page scrolls sideways: ${page.scrollWidth} > ${page.clientWidth}`);
  const scrolls = (e) => { const o = getComputedStyle(e).overflowX; return o === 'auto' || o === 'scroll' || o === 'hidden'; };
  for (const e of document.body.querySelectorAll('*')) {
    const r = e.getBoundingClientRect();
    if (r.width === 0 || r.right <= page.clientWidth + slack) continue;
    let p = e.parentElement, clipped = false;
    while (p && p !== document.body && !clipped) { clipped = scrolls(p); p = p.parentElement; }
    if (!clipped) bad.push(`${name(e)} reaches past the page (right ${Math.round(r.right)} > ${page.clientWidth})`);
  }
  return bad;
})()
