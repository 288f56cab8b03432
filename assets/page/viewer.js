// clumpkit page: the 3-D view (three.js) of a particle, a specimen's spheres or a particle's cells.
'use strict';

(function () {
  const K = window.clumpkitShared;
  const el = K.el;

  // A view in `container` that turns by dragging and zooms by the wheel; its first render marks
  // the page's first view.
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
    const orbit = { theta: 0.8, phi: 1.1, dist: 1, r: 1, target: new THREE.Vector3() };
    function place() {
      const s = Math.sin(orbit.phi);
      camera.position.set(orbit.target.x + orbit.dist * s * Math.cos(orbit.theta),
        orbit.target.y + orbit.dist * s * Math.sin(orbit.theta), orbit.target.z + orbit.dist * Math.cos(orbit.phi));
      camera.up.set(0, 0, 1);
      camera.lookAt(orbit.target);
    }
    let drawn = false;
    function draw() {
      const w = canvas.clientWidth, h = canvas.clientHeight;
      if (!w || !h) return;  // not laid out (hidden): the next size redraws
      renderer.setSize(w, h, false);
      // The near and far planes hug the object (its bounds lie within 1.5 r of the target), so the
      // depth buffer's precision is spent on it at any zoom: with a near plane fixed at 1 % of r a
      // mesh and the spheres touching it speckled (worse zoomed out, or with a 16-bit depth
      // buffer), and zooming out past a fixed far plane emptied the view.
      camera.near = Math.max(orbit.dist - 2 * orbit.r, orbit.dist * 0.01);
      camera.far = orbit.dist + 2 * orbit.r;
      camera.aspect = w / h; camera.updateProjectionMatrix();
      place();
      renderer.render(scene, camera);
    }
    function render() {
      draw();
      drawn = true;
      K.markFirstView();
    }
    // The view takes its column's width (page.css), so a resized window or a re-wrapped row
    // redraws it at the new size; the canvas is laid out absolutely, so drawing never resizes it.
    new ResizeObserver(() => { if (drawn) draw(); }).observe(box);
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
      orbit.r = r;
    }
    // Spheres [x, y, z, r, ...] of one colour in one instanced mesh (three.js r111 has no
    // per-instance colour).
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
      // A translucent triangle mesh with its edges: v flat x, y, z; f flat vertex indices.
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

  K.Viewer = Viewer;
})();
