// clumpkit page: builds the page from page/data.js with its kind's script (the last one loaded).
'use strict';

(function () {
  const K = window.clumpkitShared;

  function start() {
    const D = window.CLUMPKIT_PAGE;
    document.title = D.title;
    document.querySelector('header h1').textContent = D.title;
    document.querySelector('header p').textContent = D.subtitle;
    // library, specimen, crush; test (element tests and CPTs) the rest, as page.cpp's kinds.
    (K.kinds[D.kind] || K.kinds.test)(D);
    const report = K.section('Report');
    // A folder written before units: the note above the particles' table where the page has one
    // (library, crush), else above the report.
    const note = document.getElementById('table') ? null : K.unitsNote(D);
    if (note) report.appendChild(note);
    report.appendChild(K.reportTable(D.folders));
    if (D.images && D.images.length) K.gallery(D.images);
    K.state.ready = true;
  }
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
  else start();
})();
