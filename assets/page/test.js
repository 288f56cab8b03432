// clumpkit page of an element test or CPT, or several of one kind: their curves as plots.
'use strict';

(function () {
  const K = window.clumpkitShared;
  const el = K.el;

  // D: window.CLUMPKIT_PAGE of kind test (plots; docs/pages.md).
  K.kinds.test = function (D) {
    const s = K.section('Curves');
    const row = el('div', { class: 'row' });
    s.appendChild(row);
    for (const p of D.plots) row.appendChild(K.plot(p));
    K.markFirstView();
  };
})();
