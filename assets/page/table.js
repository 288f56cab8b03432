// clumpkit page: a sortable, filterable table of a page's rows (library and crush pages).
'use strict';

(function () {
  const K = window.clumpkitShared;
  const el = K.el, fmt = K.fmt;

  // spec: {columns, units, rows} (docs/pages.md); onPick(row, index) on a click on a row; note an
  // element shown above the table, or null. A header shows its column's unit; sorting, filtering
  // ("volume > 1e-6") and copying go by the bare name and the values.
  function dataTable(spec, onPick, note) {
    const cols = spec.columns, units = spec.units || [];
    const numeric = cols.map((_, c) => spec.rows.every((r) => typeof r[c] === 'number'));
    let order = spec.rows.map((_, i) => i);
    let sortCol = -1, sortDir = 1, filter = '';
    const thead = el('thead'), tbody = el('tbody');
    const table = K.copyFull(el('table', { id: 'table' }, [thead, tbody]));
    const headRow = el('tr');
    cols.forEach((name, c) => {
      const th = el('th', { 'data-col': name, 'data-unit': units[c] || '', class: numeric[c] ? '' : 'text', text: K.unitLabel(name, units[c]) });
      th.addEventListener('click', () => {
        sortDir = sortCol === c ? -sortDir : 1;
        sortCol = c;
        for (const t of headRow.children) t.classList.remove('asc', 'desc');
        th.classList.add(sortDir > 0 ? 'asc' : 'desc');
        draw();
      });
      headRow.appendChild(th);
    });
    thead.appendChild(headRow);
    // "column > value", "column < value", "column = value", or text anywhere in the row.
    function keep(row) {
      if (!filter) return true;
      const m = filter.match(/^\s*([\w.]+)\s*([<>=])\s*(\S+)\s*$/);
      if (m && cols.includes(m[1])) {
        const v = row[cols.indexOf(m[1])], x = Number(m[3]);
        if (m[2] === '<') return v < x;
        if (m[2] === '>') return v > x;
        return String(v) === m[3] || fmt(v) === m[3] || v === x;
      }
      // The full value or the shown one: a number is found by what the table shows of it.
      const f = filter.toLowerCase();
      return row.some((v) => String(v).toLowerCase().includes(f) || fmt(v).toLowerCase().includes(f));
    }
    function draw() {
      order = spec.rows.map((_, i) => i).filter((i) => keep(spec.rows[i]));
      if (sortCol >= 0)
        order.sort((a, b) => {
          const x = spec.rows[a][sortCol], y = spec.rows[b][sortCol];
          return (x < y ? -1 : x > y ? 1 : a - b) * sortDir;
        });
      tbody.textContent = '';
      for (const i of order) {
        const tr = el('tr', { 'data-row': i });
        spec.rows[i].forEach((v, c) => tr.appendChild(K.valueCell(v, numeric[c] ? '' : 'text')));
        tr.addEventListener('click', () => {
          for (const t of tbody.querySelectorAll('tr.selected')) t.classList.remove('selected');
          tr.classList.add('selected');
          onPick(spec.rows[i], i);
        });
        tbody.appendChild(tr);
      }
      count.textContent = order.length + ' of ' + spec.rows.length + ' rows';
    }
    const input = el('input', { id: 'filter', size: '34', placeholder: 'filter: text, or column > value' });
    input.addEventListener('input', () => { filter = input.value; draw(); });
    const count = el('span', { class: 'note' });
    const box = el('div', {}, (note ? [note] : []).concat([el('div', { class: 'controls' }, [input, count]), el('div', { class: 'scroll' }, [table])]));
    draw();
    return box;
  }

  K.dataTable = dataTable;
})();
