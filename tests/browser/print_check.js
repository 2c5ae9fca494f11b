// Problems a printed report or a narrow window shows (issue 37), as strings:
// - a table cell narrower than its longest word: a word broken over two
//   lines, or running out of its cell (tables wrap by column, not by word);
// - with PRINT set (the page laid out for paper): a box that scrolls
//   sideways, as on paper what it hides is cut.
// Used by print_test.py after layout_check.js (nothing wider than the page).
((PRINT) => {
  const bad = [];
  const slack = 1;
  const label = (e) => `${e.tagName.toLowerCase()}${e.id ? '#' + e.id : ''} "${(e.textContent || '').trim().slice(0, 40)}"`;
  const shown = (e) => { const r = e.getBoundingClientRect(); return r.width > 0 && r.height > 0; };
  for (const cell of document.querySelectorAll('td, th')) {
    if (!shown(cell)) continue;
    const box = cell.getBoundingClientRect();
    const walker = document.createTreeWalker(cell, NodeFilter.SHOW_TEXT);
    let reported = false;
    for (let n = walker.nextNode(); n && !reported; n = walker.nextNode()) {
      const parent = n.parentElement;
      if (!parent || !shown(parent)) continue;
      const re = /[^\s\-]+/g; // words: between spaces and hyphens (a hyphen may end a line)
      for (let m = re.exec(n.data); m && !reported; m = re.exec(n.data)) {
        const range = document.createRange();
        range.setStart(n, m.index);
        range.setEnd(n, m.index + m[0].length);
        const rects = [...range.getClientRects()].filter((r) => r.width > 0);
        const lines = new Set(rects.map((r) => Math.round(r.top)));
        const right = Math.max(...rects.map((r) => r.right));
        if (lines.size > 1) {
          bad.push(`${label(cell)}: the word "${m[0].slice(0, 30)}" is broken over ${lines.size} lines (cell ${Math.round(box.width)} px wide)`);
          reported = true;
        } else if (right > box.right + slack) {
          bad.push(`${label(cell)}: the word "${m[0].slice(0, 30)}" runs out of its cell (${Math.round(right)} > ${Math.round(box.right)})`);
          reported = true;
        }
      }
    }
  }
  if (PRINT) {
    for (const e of document.body.querySelectorAll('*')) {
      const o = getComputedStyle(e).overflowX;
      if ((o === 'auto' || o === 'scroll' || o === 'hidden') && shown(e) && e.scrollWidth > e.clientWidth + slack) {
        bad.push(`${label(e)}: printed, ${e.scrollWidth - e.clientWidth} px of it are cut (it scrolls sideways)`);
      }
    }
  }
  return bad;
})
