// clumpkit page of a specimen: its spheres in 3-D, coloured by a choice, cut at a height.
'use strict';

(function () {
  const K = window.clumpkitShared;
  const el = K.el, fmt = K.fmt;

  // D: window.CLUMPKIT_PAGE of kind specimen (spheres; docs/pages.md).
  K.kinds.specimen = function (D) {
    const S = D.spheres;
    const s = K.section('Specimen: ' + S.total + ' spheres' + (S.shown < S.total ? ' (every ' + S.stride + 'th shown: ' + S.shown + ')' : ''));
    const viewer = K.Viewer(s);
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
    // Sphere i's colour when coloured by `by`.
    function bucket(by, i) {
      if (by === 'body') return K.paletteColour(S.body[i]);
      if (by === 'kind') return S.kind[i] ? 0xc0392b : 0x2e6fbf;
      if (by === 'zone') return K.paletteColour(S.zone[i]);
      if (by === 'porosity band') {
        const b = band(i);
        if (b < 0) return 0xcccccc;
        return K.rampColour(phi > plo ? (S.bands.porosity[b] - plo) / (phi - plo) : 0);
      }
      return K.rampColour(rmax > rmin ? (S.r[i] - rmin) / (rmax - rmin) : 0);
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
  };
})();
