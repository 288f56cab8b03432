// clumpkit page of a crushing run: the results table, a clicked particle's curve and its cells.
'use strict';

(function () {
  const K = window.clumpkitShared;
  const el = K.el;

  // The cells of a particle ({cells: [{v, f, p0, p1, q, fragment}]}, docs/pages.md) in `viewer`,
  // each polygon fanned into triangles, one mesh per fragment's colour; after the test a vertex
  // v is at q·(v − p0) + p1.
  function drawCells(viewer, shown, after) {
    viewer.clear();
    const groups = new Map(), lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
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
      const colour = K.paletteColour(c.fragment - 1);
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
      // The faces pushed back a depth step (polygon offset), so their edges, which lie in them,
      // draw whole instead of dashed where the depth buffer rounds the tie either way.
      viewer.add(new THREE.Mesh(geo, new THREE.MeshPhongMaterial({ color: colour, flatShading: true, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 })));
      viewer.add(new THREE.LineSegments(new THREE.EdgesGeometry(geo, 20), new THREE.LineBasicMaterial({ color: 0x333333 })));
    }
    viewer.fit(lo, hi);
    viewer.legend.textContent = shown.cells.length + ' cells, ' + fragments + ' fragments at the end; ' + (after ? 'after' : 'before') + ' the test';
    viewer.render();
  }

  // D: window.CLUMPKIT_PAGE of kind crush (table, curves, cells, cells_ids; docs/pages.md).
  K.kinds.crush = function (D) {
    const { left, right } = K.twoColumns('Particles crushed (' + D.table.rows.length + '): click one for its force against travel');
    const idCol = D.table.columns.indexOf('id');
    // The curve and the cells side by side where the left column is wide enough.
    const curveBox = el('div'), cellsBox = el('div', { class: 'grow' });
    left.classList.add('row');
    left.appendChild(curveBox); left.appendChild(cellsBox);
    const viewer = D.cells_ids.length ? K.Viewer(cellsBox) : null;
    const when = el('select', { id: 'cells-when' });
    for (const k of ['after', 'before']) when.appendChild(el('option', { value: k, text: 'cells ' + k + ' the test' }));
    if (viewer) cellsBox.appendChild(el('div', { class: 'controls' }, [when, el('span', { class: 'note', text: 'coloured by fragment at the end' })]));
    let shown = null;
    const redraw = () => { if (shown) drawCells(viewer, shown, when.value === 'after'); };
    when.addEventListener('change', redraw);
    // The particle's cells script cells/NNNNN.js calls clumpkit_cells({cells}).
    function show(r) {
      const id = r[idCol], c = D.curves[String(id)];
      curveBox.textContent = '';
      if (c) curveBox.appendChild(K.plot({ title: 'particle ' + id, x: 'platen travel (mm)', y: 'force (N)', series: [{ label: 'particle ' + id, x: c.x, y: c.y }] }));
      if (!viewer || !D.cells_ids.includes(id)) return;
      K.loadPart('cells-script', D.cells + String(id).padStart(5, '0') + '.js', 'clumpkit_cells', (p) => { shown = p; redraw(); });
    }
    right.appendChild(K.dataTable(D.table, show, K.unitsNote(D)));
    show(D.table.rows[0]);
    K.markFirstView();
  };
})();
