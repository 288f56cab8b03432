// clumpkit page: a static, offline view of clumpkit output folders. No build step, no network:
// the data come from page/data.js (window.CLUMPKIT_PAGE) and, for a library particle, from
// page/parts/NNNNN.js loaded on demand by a <script> tag (browsers refuse fetch() from file://).
// three.js (Debian's libjs-three, the global THREE) draws the 3-D views.
'use strict';

(function () {
  const D = window.CLUMPKIT_PAGE;
  const state = { ready: false, firstViewMs: null, viewDrawn: false, errors: [] };
  window.clumpkitPage = state;

  // ---- small DOM helpers ----
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
  function fmt(v) {
    if (typeof v !== 'number') return String(v);
    if (!isFinite(v)) return String(v);
    if (Number.isInteger(v) && Math.abs(v) < 1e9) return String(v);
    const a = Math.abs(v);
    if (a !== 0 && (a < 1e-3 || a >= 1e6)) return v.toExponential(4).replace(/\.?0+e/, 'e');
    return String(Number(v.toPrecision(5)));
  }
  function section(title) {
    const s = el('section', {}, [el('h2', { text: title })]);
    document.querySelector('main').appendChild(s);
    return s;
  }

  // ---- key-value tables of the reports (one column per folder) ----
  function reportTable(folders) {
    const keys = [];
    for (const f of folders) for (const k of Object.keys(f.report)) if (!keys.includes(k)) keys.push(k);
    const head = el('tr', {}, [el('th', { class: 'text', text: 'report' })]);
    for (const f of folders) head.appendChild(el('th', { class: 'text', text: f.name }));
    const body = el('tbody');
    for (const k of keys) {
      const tr = el('tr', { 'data-key': k }, [el('td', { class: 'text', text: k })]);
      for (const f of folders) tr.appendChild(el('td', { text: k in f.report ? fmt(f.report[k]) : '' }));
      body.appendChild(tr);
    }
    return el('table', { class: 'kv', id: 'report' }, [el('thead', {}, [head]), body]);
  }

  // ---- a sortable, filterable table; onPick(row) on a click ----
  function dataTable(spec, onPick) {
    const cols = spec.columns;
    const numeric = cols.map((_, c) => spec.rows.every((r) => typeof r[c] === 'number'));
    let order = spec.rows.map((_, i) => i);
    let sortCol = -1, sortDir = 1, filter = '';
    const thead = el('thead'), tbody = el('tbody');
    const table = el('table', { id: 'table' }, [thead, tbody]);
    const headRow = el('tr');
    cols.forEach((name, c) => {
      const th = el('th', { 'data-col': name, class: numeric[c] ? '' : 'text', text: name });
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
        return String(v) === m[3] || v === x;
      }
      const f = filter.toLowerCase();
      return row.some((v) => String(v).toLowerCase().includes(f));
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
        spec.rows[i].forEach((v, c) => tr.appendChild(el('td', { class: numeric[c] ? '' : 'text', text: fmt(v) })));
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
    const box = el('div', {}, [el('div', { class: 'controls' }, [input, count]), el('div', { class: 'scroll' }, [table])]);
    draw();
    return box;
  }

  // ---- line plots on a canvas, with a readout of the nearest point ----
  const COLOURS = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2', '#17becf'];
  function niceTicks(lo, hi, n) {
    if (!(hi > lo)) { hi = lo + 1; }
    const step0 = (hi - lo) / n, mag = Math.pow(10, Math.floor(Math.log10(step0)));
    const step = [1, 2, 5, 10].map((m) => m * mag).find((s) => s >= step0);
    const ticks = [];
    for (let t = Math.ceil(lo / step) * step; t <= hi + 1e-9 * step; t += step) ticks.push(t);
    return ticks;
  }
  function plot(spec) {
    const canvas = el('canvas', { class: 'plot', 'data-title': spec.title });
    const readout = el('div', { class: 'note', text: ' ' });
    const box = el('div', {}, [el('div', { text: spec.title }), canvas, readout]);
    let xs = [], ys = [];
    for (const s of spec.series) { xs = xs.concat(s.x); ys = ys.concat(s.y); }
    const finite = (a) => a.filter((v) => isFinite(v));
    const xlo = Math.min(...finite(xs)), xhi = Math.max(...finite(xs));
    const ylo = Math.min(...finite(ys)), yhi = Math.max(...finite(ys));
    const m = { l: 76, r: 12, t: 10, b: 40 };
    function geometry() {
      const w = canvas.clientWidth, h = canvas.clientHeight;
      return { w, h, sx: (x) => m.l + (x - xlo) / ((xhi - xlo) || 1) * (w - m.l - m.r),
        sy: (y) => h - m.b - (y - ylo) / ((yhi - ylo) || 1) * (h - m.t - m.b) };
    }
    function draw(mark) {
      const g = geometry(), ratio = window.devicePixelRatio || 1;
      canvas.width = g.w * ratio; canvas.height = g.h * ratio;
      const c = canvas.getContext('2d');
      c.scale(ratio, ratio);
      c.fillStyle = '#fff'; c.fillRect(0, 0, g.w, g.h);
      c.strokeStyle = '#999'; c.fillStyle = '#333'; c.font = '11px sans-serif';
      c.strokeRect(m.l, m.t, g.w - m.l - m.r, g.h - m.t - m.b);
      for (const t of niceTicks(xlo, xhi, 6)) {
        c.fillText(fmt(+t.toPrecision(6)), g.sx(t) - 12, g.h - m.b + 14);
        c.beginPath(); c.moveTo(g.sx(t), g.h - m.b); c.lineTo(g.sx(t), g.h - m.b + 4); c.stroke();
      }
      c.textAlign = 'right';
      for (const t of niceTicks(ylo, yhi, 5)) {
        c.fillText(fmt(+t.toPrecision(6)), m.l - 6, g.sy(t) + 4);
        c.beginPath(); c.moveTo(m.l - 4, g.sy(t)); c.lineTo(m.l, g.sy(t)); c.stroke();
      }
      c.textAlign = 'center';
      c.fillText(spec.x, (m.l + g.w - m.r) / 2, g.h - 6);
      c.save(); c.translate(10, (m.t + g.h - m.b) / 2); c.rotate(-Math.PI / 2); c.fillText(spec.y, 0, 0); c.restore();
      c.textAlign = 'left';
      spec.series.forEach((s, k) => {
        c.strokeStyle = COLOURS[k % COLOURS.length]; c.lineWidth = 1.5; c.beginPath();
        let first = true;
        for (let i = 0; i < s.x.length; ++i) {
          if (!isFinite(s.x[i]) || !isFinite(s.y[i])) continue;
          if (first) c.moveTo(g.sx(s.x[i]), g.sy(s.y[i])); else c.lineTo(g.sx(s.x[i]), g.sy(s.y[i]));
          first = false;
        }
        c.stroke();
        if (spec.series.length > 1) {
          c.fillStyle = COLOURS[k % COLOURS.length];
          c.fillText(s.label, m.l + 8, m.t + 14 + 13 * k);
        }
      });
      if (mark) {
        c.fillStyle = '#000'; c.beginPath(); c.arc(g.sx(mark[0]), g.sy(mark[1]), 3.5, 0, 7); c.fill();
      }
    }
    canvas.addEventListener('mousemove', (e) => {
      const g = geometry(), r = canvas.getBoundingClientRect();
      const px = e.clientX - r.left, py = e.clientY - r.top;
      let best = null, bd = Infinity;
      for (const s of spec.series)
        for (let i = 0; i < s.x.length; ++i) {
          const d = Math.hypot(g.sx(s.x[i]) - px, g.sy(s.y[i]) - py);
          if (d < bd) { bd = d; best = [s.x[i], s.y[i], s.label]; }
        }
      if (best) { readout.textContent = best[2] + ': ' + spec.x + ' = ' + fmt(best[0]) + ', ' + spec.y + ' = ' + fmt(best[1]); draw(best); }
    });
    requestAnimationFrame(() => draw(null));
    return box;
  }

  // ---- 3-D view: a translucent mesh with spheres, or a whole specimen, instanced ----
  function Viewer(container) {
    const canvas = el('canvas', { id: 'view3d' });
    const legend = el('div', { class: 'legend' });
    const box = el('div', { class: 'view' }, [canvas, legend]);
    container.appendChild(box);
    const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setClearColor(0xffffff, 1);
    const scene = new THREE.Scene();
    const camera = new THREE.PerspectiveCamera(35, 4 / 3, 1e-4, 1e4);
    scene.add(new THREE.AmbientLight(0xffffff, 0.45));
    const sun = new THREE.DirectionalLight(0xffffff, 0.75);
    camera.add(sun); sun.position.set(1, 2, 3);
    scene.add(camera);
    let group = new THREE.Group();
    scene.add(group);
    const orbit = { theta: 0.8, phi: 1.1, dist: 1, target: new THREE.Vector3() };
    function place() {
      const s = Math.sin(orbit.phi);
      camera.position.set(orbit.target.x + orbit.dist * s * Math.cos(orbit.theta),
        orbit.target.y + orbit.dist * s * Math.sin(orbit.theta), orbit.target.z + orbit.dist * Math.cos(orbit.phi));
      camera.up.set(0, 0, 1);
      camera.lookAt(orbit.target);
    }
    function render() {
      const w = canvas.clientWidth, h = canvas.clientHeight;
      renderer.setSize(w, h, false);
      camera.aspect = w / h; camera.updateProjectionMatrix();
      place();
      renderer.render(scene, camera);
      if (!state.viewDrawn) { state.viewDrawn = true; state.firstViewMs = performance.now(); }
    }
    let drag = null;
    canvas.addEventListener('mousedown', (e) => { drag = [e.clientX, e.clientY]; });
    window.addEventListener('mouseup', () => { drag = null; });
    window.addEventListener('mousemove', (e) => {
      if (!drag) return;
      orbit.theta -= (e.clientX - drag[0]) * 0.01;
      orbit.phi = Math.min(3.1, Math.max(0.05, orbit.phi - (e.clientY - drag[1]) * 0.01));
      drag = [e.clientX, e.clientY];
      render();
    });
    canvas.addEventListener('wheel', (e) => { e.preventDefault(); orbit.dist *= Math.exp(e.deltaY * 0.001); render(); }, { passive: false });
    function clear() {
      scene.remove(group);
      group.traverse((o) => { if (o.geometry) o.geometry.dispose(); if (o.material) o.material.dispose(); });
      group = new THREE.Group();
      scene.add(group);
    }
    function fit(lo, hi) {
      orbit.target.set((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
      // The largest extent, not the diagonal: a tall specimen fills the view.
      const r = 0.6 * Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) || 1;
      orbit.dist = 1.6 * r / Math.tan(camera.fov * Math.PI / 360);
      camera.near = r * 0.01; camera.far = r * 100;
    }
    // Spheres of one colour in one instanced mesh (three.js r111 has no per-instance colour).
    function spheres(list, colour, detail) {
      const geo = new THREE.IcosahedronBufferGeometry(1, detail);
      const mesh = new THREE.InstancedMesh(geo, new THREE.MeshLambertMaterial({ color: colour }), list.length);
      const mat = new THREE.Matrix4();
      list.forEach((s, i) => { mat.makeScale(s[3], s[3], s[3]); mat.setPosition(s[0], s[1], s[2]); mesh.setMatrixAt(i, mat); });
      mesh.instanceMatrix.needsUpdate = true;
      group.add(mesh);
    }
    return {
      render, clear, fit, spheres, legend,
      add(object) { group.add(object); },
      mesh(v, f) {
        const geo = new THREE.BufferGeometry();
        geo.setAttribute('position', new THREE.Float32BufferAttribute(v, 3));
        geo.setIndex(f);
        const flat = geo.toNonIndexed();
        flat.computeVertexNormals();
        group.add(new THREE.Mesh(flat, new THREE.MeshPhongMaterial({ color: 0xc8b27a, transparent: true, opacity: 0.35, depthWrite: false, side: THREE.DoubleSide })));
        group.add(new THREE.LineSegments(new THREE.EdgesGeometry(flat, 20), new THREE.LineBasicMaterial({ color: 0x7a6a40 })));
      },
    };
  }

  // ---- page kinds ----
  // A section of two columns: the views on the left, the table on the right.
  function twoColumns(title) {
    const s = section(title);
    const row = el('div', { class: 'row' });
    s.appendChild(row);
    const left = el('div'), right = el('div');
    row.appendChild(left); row.appendChild(right);
    return { left, right };
  }

  // Loads one particle's data script (browsers refuse fetch() from file://): the script calls
  // window[callback], which is set to `onData` first; the previous script of that id goes.
  function loadPart(id, src, callback, onData) {
    window[callback] = onData;
    const old = document.getElementById(id);
    if (old) old.remove();
    document.body.appendChild(el('script', { id, src }));
  }

  function libraryPage() {
    const { left, right } = twoColumns('Particles (' + D.table.rows.length + ')');
    const viewer = Viewer(left);
    const info = el('div', { class: 'note', id: 'part-info' });
    left.appendChild(info);
    const idCol = D.table.columns.indexOf('id');
    function show(r) {
      const id = r[idCol], name = String(id).padStart(5, '0');
      loadPart('part-script', D.parts + name + '.js', 'clumpkit_part', (p) => {
        viewer.clear();
        viewer.mesh(p.v, p.f);
        viewer.spheres(p.s.filter((q) => !q[4]), 0x3b6fb6, 2);
        const out = p.s.filter((q) => q[4]);
        if (out.length) viewer.spheres(out, 0xd62728, 2);
        viewer.fit(p.lo, p.hi);
        viewer.legend.textContent = 'particle ' + id + ': ' + p.s.length + ' spheres, ' + out.length + ' reaching outside the mesh (red)';
        viewer.render();
      });
      info.textContent = 'drag to turn, wheel to zoom';
    }
    right.appendChild(dataTable(D.table, show));
    show(D.table.rows[0]);
    right.querySelector('tbody tr').classList.add('selected');
  }

  function specimenPage() {
    const S = D.spheres;
    const s = section('Specimen: ' + S.total + ' spheres' + (S.shown < S.total ? ' (every ' + S.stride + 'th shown: ' + S.shown + ')' : ''));
    const viewer = Viewer(s);
    const select = el('select', { id: 'colour-by' });
    for (const k of ['body', 'size', 'kind', 'zone'].concat(S.bands ? ['porosity band'] : [])) select.appendChild(el('option', { value: k, text: 'colour by ' + k }));
    // A sphere's porosity band (equal heights of the report's measurement region), -1 outside.
    function band(i) {
      const B = S.bands, n = B.porosity.length, t = (S.z[i] - B.z_lo) / (B.z_hi - B.z_lo);
      return t < 0 || t >= 1 ? -1 : Math.floor(t * n);
    }
    let plo = Infinity, phi = -Infinity;
    if (S.bands) for (const p of S.bands.porosity) { plo = Math.min(plo, p); phi = Math.max(phi, p); }
    let zmin = Infinity, zmax = -Infinity, rmin = Infinity, rmax = 0;
    for (let i = 0; i < S.shown; ++i) {
      zmin = Math.min(zmin, S.z[i] - S.r[i]); zmax = Math.max(zmax, S.z[i] + S.r[i]);
      rmin = Math.min(rmin, S.r[i]); rmax = Math.max(rmax, S.r[i]);
    }
    const slider = el('input', { id: 'slice', type: 'range', min: '0', max: '1000', value: '1000' });
    const label = el('span', { class: 'note' });
    s.appendChild(el('div', { class: 'controls' }, [select, el('span', { text: 'show below height' }), slider, label]));
    const palette = [0x1f77b4, 0xd62728, 0x2ca02c, 0xff7f0e, 0x9467bd, 0x8c564b, 0xe377c2, 0x17becf, 0xbcbd22, 0x7f7f7f, 0xaec7e8, 0xffbb78];
    const ramp = [0x440154, 0x46327e, 0x365c8d, 0x277f8e, 0x1fa187, 0x4ac16d, 0xa0da39, 0xfde725];
    function bucket(by, i) {
      if (by === 'body') return palette[S.body[i] % palette.length];
      if (by === 'kind') return S.kind[i] ? 0xc0392b : 0x2e6fbf;
      if (by === 'zone') return palette[(S.zone[i] + palette.length) % palette.length];
      if (by === 'porosity band') {
        const b = band(i);
        if (b < 0) return 0xcccccc;
        const t = phi > plo ? (S.bands.porosity[b] - plo) / (phi - plo) : 0;
        return ramp[Math.min(ramp.length - 1, Math.floor(t * ramp.length))];
      }
      const t = rmax > rmin ? (S.r[i] - rmin) / (rmax - rmin) : 0;
      return ramp[Math.min(ramp.length - 1, Math.floor(t * ramp.length))];
    }
    function draw() {
      const cut = zmin + (zmax - zmin) * slider.value / 1000;
      label.textContent = fmt(cut) + ' m';
      const groups = new Map();
      let n = 0;
      for (let i = 0; i < S.shown; ++i) {
        if (S.z[i] > cut) continue;
        const c = bucket(select.value, i);
        if (!groups.has(c)) groups.set(c, []);
        groups.get(c).push([S.x[i], S.y[i], S.z[i], S.r[i]]);
        ++n;
      }
      viewer.clear();
      const detail = S.shown > 50000 ? 0 : 1;
      for (const [c, list] of groups) viewer.spheres(list, c, detail);
      viewer.legend.textContent = n + ' spheres drawn, coloured by ' + select.value +
        (select.value === 'porosity band' ? ' (dark ' + fmt(plo) + ' to light ' + fmt(phi) + ', grey outside the measured region; bands from the bottom: ' + S.bands.porosity.map(fmt).join(', ') + ')' : '');
      viewer.render();
    }
    select.addEventListener('change', draw);
    slider.addEventListener('input', draw);
    viewer.fit([S.lo[0], S.lo[1], S.lo[2]], [S.hi[0], S.hi[1], S.hi[2]]);
    draw();
  }

  function plotsPage() {
    const s = section('Curves');
    const row = el('div', { class: 'row' });
    s.appendChild(row);
    for (const p of D.plots) row.appendChild(plot(p));
    state.viewDrawn = true;
    state.firstViewMs = performance.now();
  }

  function crushPage() {
    const { left, right } = twoColumns('Particles crushed (' + D.table.rows.length + '): click one for its force against travel');
    const idCol = D.table.columns.indexOf('id');
    const curveBox = el('div'), cellsBox = el('div');
    left.appendChild(curveBox); left.appendChild(cellsBox);
    const viewer = D.cells_ids.length ? Viewer(cellsBox) : null;
    const when = el('select', { id: 'cells-when' });
    for (const k of ['after', 'before']) when.appendChild(el('option', { value: k, text: 'cells ' + k + ' the test' }));
    if (viewer) cellsBox.appendChild(el('div', { class: 'controls' }, [when, el('span', { class: 'note', text: 'coloured by fragment at the end' })]));
    let shown = null;
    // The cells of a particle, each polygon fanned into triangles, one mesh per fragment's colour;
    // after the test a vertex v is at q·(v − p0) + p1.
    function drawCells() {
      if (!shown) return;
      viewer.clear();
      const palette = [0x1f77b4, 0xd62728, 0x2ca02c, 0xff7f0e, 0x9467bd, 0x8c564b, 0xe377c2, 0x17becf, 0xbcbd22, 0x7f7f7f];
      const groups = new Map(), lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
      const after = when.value === 'after';
      let fragments = 0;
      for (const c of shown.cells) {
        fragments = Math.max(fragments, c.fragment);
        const q = new THREE.Quaternion(c.q[1], c.q[2], c.q[3], c.q[0]);
        const pts = [];
        for (let i = 0; i < c.v.length; i += 3) {
          const p = new THREE.Vector3(c.v[i], c.v[i + 1], c.v[i + 2]);
          if (after) p.sub(new THREE.Vector3(...c.p0)).applyQuaternion(q).add(new THREE.Vector3(...c.p1));
          pts.push(p);
          lo[0] = Math.min(lo[0], p.x); lo[1] = Math.min(lo[1], p.y); lo[2] = Math.min(lo[2], p.z);
          hi[0] = Math.max(hi[0], p.x); hi[1] = Math.max(hi[1], p.y); hi[2] = Math.max(hi[2], p.z);
        }
        const colour = palette[(c.fragment - 1) % palette.length];
        if (!groups.has(colour)) groups.set(colour, []);
        const list = groups.get(colour);
        for (const f of c.f)
          for (let i = 1; i + 1 < f.length; ++i)
            for (const j of [f[0], f[i], f[i + 1]]) list.push(pts[j].x, pts[j].y, pts[j].z);
      }
      for (const [colour, list] of groups) {
        const geo = new THREE.BufferGeometry();
        geo.setAttribute('position', new THREE.Float32BufferAttribute(list, 3));
        geo.computeVertexNormals();
        viewer.add(new THREE.Mesh(geo, new THREE.MeshPhongMaterial({ color: colour, flatShading: true })));
        viewer.add(new THREE.LineSegments(new THREE.EdgesGeometry(geo, 20), new THREE.LineBasicMaterial({ color: 0x333333 })));
      }
      viewer.fit(lo, hi);
      viewer.legend.textContent = shown.cells.length + ' cells, ' + fragments + ' fragments at the end; ' + when.value + ' the test';
      viewer.render();
    }
    when.addEventListener('change', drawCells);
    function show(r) {
      const id = r[idCol], c = D.curves[String(id)];
      curveBox.textContent = '';
      if (c) curveBox.appendChild(plot({ title: 'particle ' + id, x: 'platen travel (mm)', y: 'force (N)', series: [{ label: 'particle ' + id, x: c.x, y: c.y }] }));
      if (!viewer || !D.cells_ids.includes(id)) return;
      loadPart('cells-script', D.cells + String(id).padStart(5, '0') + '.js', 'clumpkit_cells', (p) => { shown = p; drawCells(); });
    }
    right.appendChild(dataTable(D.table, show));
    show(D.table.rows[0]);
    state.viewDrawn = true;
    state.firstViewMs = performance.now();
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

  function start() {
    document.title = D.title;
    document.querySelector('header h1').textContent = D.title;
    document.querySelector('header p').textContent = D.subtitle;
    if (D.kind === 'library') libraryPage();
    else if (D.kind === 'specimen') specimenPage();
    else if (D.kind === 'crush') crushPage();
    else plotsPage();
    section('Report').appendChild(reportTable(D.folders));
    if (D.images && D.images.length) gallery(D.images);
    state.ready = true;
  }
  window.addEventListener('error', (e) => state.errors.push(String(e.message)));
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
  else start();
})();
