// clumpkit page: line plots on a canvas, with a readout of the nearest point (test and crush pages).
'use strict';

(function () {
  const K = window.clumpkitShared;
  const el = K.el, fmt = K.fmt;

  function niceTicks(lo, hi, n) {
    if (!(hi > lo)) { hi = lo + 1; }
    const step0 = (hi - lo) / n, mag = Math.pow(10, Math.floor(Math.log10(step0)));
    const step = [1, 2, 5, 10].map((m) => m * mag).find((s) => s >= step0);
    const ticks = [];
    for (let t = Math.ceil(lo / step) * step; t <= hi + 1e-9 * step; t += step) ticks.push(t);
    return ticks;
  }

  // spec: {title, x, y (axis labels), series: [{label, x: [...], y: [...]}]} (docs/pages.md).
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
        c.strokeStyle = K.paletteCss(k); c.lineWidth = 1.5; c.beginPath();
        let first = true;
        for (let i = 0; i < s.x.length; ++i) {
          if (!isFinite(s.x[i]) || !isFinite(s.y[i])) continue;
          if (first) c.moveTo(g.sx(s.x[i]), g.sy(s.y[i])); else c.lineTo(g.sx(s.x[i]), g.sy(s.y[i]));
          first = false;
        }
        c.stroke();
        if (spec.series.length > 1) {
          c.fillStyle = K.paletteCss(k);
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

  K.plot = plot;
})();
