// clumpkit page, shared by every kind: DOM helpers, the one palette, ramp and first-view mark.
// A static, offline page: no build step, no network, no modules (file:// refuses them). The
// scripts of page/ run in index.html's order, each in its own function, and share what they need
// through window.clumpkitShared; the data come from page/data.js (window.CLUMPKIT_PAGE) and
// per-item scripts (docs/pages.md). three.js (Debian's libjs-three, the global THREE) draws.
'use strict';

(function () {
  // What tests/browser/page_check.py reads: ready (the page built), viewDrawn and firstViewMs (its
  // first view drawn, and when), errors.
  const state = { ready: false, firstViewMs: null, viewDrawn: false, errors: [] };
  window.clumpkitPage = state;
  window.addEventListener('error', (e) => state.errors.push(String(e.message)));

  function el(tag, attrs, children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === 'text') e.textContent = v;
      else if (k === 'class') e.className = v;
      else e.setAttribute(k, v);
    }
    for (const c of children || []) e.appendChild(c);
    return e;
  }

  // Numbers as a person reads them: integers whole, others to five digits, tiny or huge ones in
  // exponent form.
  function fmt(v) {
    if (typeof v !== 'number') return String(v);
    if (!isFinite(v)) return String(v);
    if (Number.isInteger(v) && Math.abs(v) < 1e9) return String(v);
    const a = Math.abs(v);
    if (a !== 0 && (a < 1e-3 || a >= 1e6)) return v.toExponential(4).replace(/\.?0+e/, 'e');
    return String(Number(v.toPrecision(5)));
  }

  // A table cell showing v as fmt does, its full value on hover (the title) where that differs.
  function valueCell(v, cls) {
    const td = el('td', { class: cls || '', text: fmt(v) });
    if (String(v) !== td.textContent) td.title = String(v);
    return td;
  }

  // A copy from `table` takes the selected cells' full values (titles), a row a line, cells
  // tab-separated: a spreadsheet gets what the data hold, not the rounded text.
  function copyFull(table) {
    table.addEventListener('copy', (e) => {
      const sel = document.getSelection(), lines = [];
      for (const tr of table.rows) {
        const cells = [...tr.cells].filter((td) => sel.containsNode(td, true));
        if (cells.length) lines.push(cells.map((td) => td.title || td.textContent).join('\t'));
      }
      if (!lines.length) return;
      e.clipboardData.setData('text/plain', lines.join('\n'));
      e.preventDefault();
    });
    return table;
  }

  function section(title) {
    const s = el('section', {}, [el('h2', { text: title })]);
    document.querySelector('main').appendChild(s);
    return s;
  }

  // A section of two columns: the views on the left (growing to the row's width when the table
  // wraps below), the table on the right.
  function twoColumns(title) {
    const s = section(title);
    const row = el('div', { class: 'row' });
    s.appendChild(row);
    const left = el('div', { class: 'grow' }), right = el('div');
    row.appendChild(left); row.appendChild(right);
    return { left, right };
  }

  // Loads one item's data script (browsers refuse fetch() from file://): the script calls
  // window[callback], which is set to `onData` first; the previous script of that id goes.
  function loadPart(id, src, callback, onData) {
    window[callback] = onData;
    const old = document.getElementById(id);
    if (old) old.remove();
    document.body.appendChild(el('script', { id, src }));
  }

  // The one palette of categories (bodies, zones, fragments, curves); colours repeat beyond it.
  const PALETTE = [0x1f77b4, 0xd62728, 0x2ca02c, 0xff7f0e, 0x9467bd, 0x8c564b, 0xe377c2, 0x17becf, 0xbcbd22, 0x7f7f7f, 0xaec7e8, 0xffbb78];
  // Category k's colour as a number (three.js), any integer k (a zone may be -1).
  function paletteColour(k) {
    const n = PALETTE.length;
    return PALETTE[((k % n) + n) % n];
  }
  // The same as CSS (canvas plots).
  function paletteCss(k) {
    return '#' + paletteColour(k).toString(16).padStart(6, '0');
  }

  // The one ramp of quantities (viridis, dark to light) in eight steps: t in [0, 1].
  const RAMP = [0x440154, 0x46327e, 0x365c8d, 0x277f8e, 0x1fa187, 0x4ac16d, 0xa0da39, 0xfde725];
  function rampColour(t) {
    return RAMP[Math.min(RAMP.length - 1, Math.floor(t * RAMP.length))];
  }

  // The page's first view is drawn (a 3-D view rendered, or the plots placed): stamped once, the
  // time the browser tests hold against --max-first-view.
  function markFirstView() {
    if (state.viewDrawn) return;
    state.viewDrawn = true;
    state.firstViewMs = performance.now();
  }

  // A column's or a report row's label with its unit as the files write it (docs/units.md):
  // "volume [m3]", "porosity [1]" for a dimensionless number; the bare name without one (text,
  // or a folder written before units).
  function unitLabel(name, unit) {
    return unit ? name + ' [' + unit + ']' : name;
  }

  // The note of a page whose folders were written before clumpkit recorded units, null otherwise.
  function unitsNote(D) {
    if (D.units_recorded !== false) return null;
    return el('p', { class: 'note', id: 'units-note', text: 'units not recorded in this folder (written before clumpkit recorded units); recipes are SI' });
  }

  // The reports as key-value rows, one column per folder, each key with its unit (the first
  // folder's that records one).
  function reportTable(folders) {
    const keys = [], units = {};
    for (const f of folders) {
      for (const k of Object.keys(f.report)) if (!keys.includes(k)) keys.push(k);
      for (const [k, u] of Object.entries(f.units || {})) if (!(k in units)) units[k] = u;
    }
    const head = el('tr', {}, [el('th', { class: 'text', text: 'report' })]);
    for (const f of folders) head.appendChild(el('th', { class: 'text', text: f.name }));
    const body = el('tbody');
    for (const k of keys) {
      const tr = el('tr', { 'data-key': k }, [el('td', { class: 'text', text: unitLabel(k, units[k]) })]);
      for (const f of folders) tr.appendChild(valueCell(k in f.report ? f.report[k] : ''));
      body.appendChild(tr);
    }
    return copyFull(el('table', { class: 'kv', id: 'report' }, [el('thead', {}, [head]), body]));
  }

  function gallery(images) {
    const s = section('Images (' + images.length + ')');
    const g = el('div', { class: 'gallery' });
    for (const im of images) {
      const img = el('img', { src: im.src, loading: 'lazy', alt: im.caption });
      g.appendChild(el('figure', {}, [el('a', { href: im.src }, [img]), el('figcaption', { text: im.caption })]));
    }
    s.appendChild(g);
  }

  // kinds: each page kind's script adds kinds[D.kind] = function (D), which builds its sections.
  window.clumpkitShared = {
    state, el, fmt, valueCell, copyFull, section, twoColumns, loadPart, paletteColour, paletteCss,
    rampColour, markFirstView, unitLabel, unitsNote, reportTable, gallery, kinds: {},
  };
})();
