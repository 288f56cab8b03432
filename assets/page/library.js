// clumpkit page of a library or shape set: the particles' table, a clicked one in 3-D.
'use strict';

(function () {
  const K = window.clumpkitShared;
  const el = K.el;

  // D: window.CLUMPKIT_PAGE of kind library (table, parts; docs/pages.md).
  K.kinds.library = function (D) {
    const { left, right } = K.twoColumns('Particles (' + D.table.rows.length + ')');
    const viewer = K.Viewer(left);
    const info = el('div', { class: 'note', id: 'part-info' });
    left.appendChild(info);
    const idCol = D.table.columns.indexOf('id');
    // The particle's script parts/NNNNN.js calls clumpkit_part({v, f, s, lo, hi}).
    function show(r) {
      const id = r[idCol], name = String(id).padStart(5, '0');
      K.loadPart('part-script', D.parts + name + '.js', 'clumpkit_part', (p) => {
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
    right.appendChild(K.dataTable(D.table, show, K.unitsNote(D)));
    show(D.table.rows[0]);
    right.querySelector('tbody tr').classList.add('selected');
  };
})();
