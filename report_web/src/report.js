// The HTML report of `fspm report --html` (docs/experiments.md). Classic script, no modules and no
// fetch(), so the page works from file://. Reads window.FSPM_REPORT (data.js, written by fspm):
// the Markdown report, the runs, the comparison pairs and the trees to show, and builds the page:
// the report's text and tables (sortable, filterable, paged), interactive plots (Plotly) and 3D
// views of trees (three.js).
(function () {
  'use strict';
  const D = window.FSPM_REPORT;
  const kPageRows = 25; // table rows per page
  const kRunIndex = new Map();
  D.runs.run.forEach((r, i) => kRunIndex.set(r, i));

  // ---------- small helpers ----------
  function el(tag, attrs, children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === 'text') e.textContent = v;
      else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
      else e.setAttribute(k, v);
    }
    for (const c of children || []) e.appendChild(c);
    return e;
  }
  // Four significant digits, as the Markdown tables print them.
  function fmt(v) {
    if (v === null || v === undefined || !Number.isFinite(v)) return '-';
    return String(Number(v.toPrecision(4)));
  }
  function escapeHtml(s) {
    return String(s).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
  }
  function metricInfo(name) {
    return D.metrics.find((m) => m.name === name) || { name, unit: '' };
  }
  function metricLabel(name) {
    const u = metricInfo(name).unit;
    return u ? `${name} (${u})` : name;
  }
  // "run 12, seed 345<br>a = 1<br>b = 2": what hovering a run shows.
  function runText(run) {
    const i = kRunIndex.get(run);
    if (i === undefined) return `run ${run}`;
    let s = `run ${run}, seed ${D.runs.seed[i]}`;
    for (const p of D.swept) s += `<br>${escapeHtml(p)} = ${escapeHtml(D.runs.parameters[p][i])}`;
    return s;
  }

  // ---------- the Markdown report ----------
  // Rendered by safe_markdown.js: no raw HTML, no script, links and images limited to safe URLs.
  function renderMarkdown(target) {
    target.replaceChildren(window.fspmSafeMarkdown(D.markdown));
  }

  // The number a table cell starts with ("12.3 ± 1.2" -> 12.3), NaN for text.
  function cellNumber(text) {
    const m = /^\s*(-?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?)(\s|$|\s*±)/i.exec(text);
    return m ? parseFloat(m[1]) : NaN;
  }

  // Sorting by a header click (again: reversed), a filter box, pages of kPageRows rows.
  function enhanceTable(table) {
    const tbody = table.tBodies[0];
    if (!tbody) return;
    const rows = Array.from(tbody.rows);
    table._fspmRows = rows; // every row, in the order fspm wrote them (tests read them)
    const state = { col: -1, dir: 1, filter: '', page: 0 };
    const info = el('span', { class: 'fspm-table-info' });
    const filter = el('input', { type: 'search', placeholder: 'filter rows', class: 'fspm-filter' });
    const prev = el('button', { text: '‹ previous', class: 'fspm-prev' });
    const next = el('button', { text: 'next ›', class: 'fspm-next' });
    const bar = el('div', { class: 'fspm-table-bar' }, [filter, prev, next, info]);
    table.parentNode.insertBefore(bar, table);
    const wrap = el('div', { class: 'fspm-table-wrap' });
    table.parentNode.insertBefore(wrap, table);
    wrap.appendChild(table);
    function render() {
      let shown = rows.filter((r) => !state.filter || r.textContent.toLowerCase().includes(state.filter));
      if (state.col >= 0) {
        const key = (r) => r.cells[state.col] ? r.cells[state.col].textContent : '';
        shown = shown.slice().sort((a, b) => {
          const x = key(a), y = key(b);
          const nx = cellNumber(x), ny = cellNumber(y);
          if (!isNaN(nx) && !isNaN(ny)) return state.dir * (nx - ny);
          if (!isNaN(nx) !== !isNaN(ny)) return isNaN(nx) ? 1 : -1; // "-" last
          return state.dir * x.localeCompare(y, undefined, { numeric: true });
        });
      }
      const pages = Math.max(1, Math.ceil(shown.length / kPageRows));
      state.page = Math.min(state.page, pages - 1);
      tbody.replaceChildren(...shown.slice(state.page * kPageRows, (state.page + 1) * kPageRows));
      const paged = rows.length > kPageRows;
      prev.hidden = next.hidden = !paged;
      prev.disabled = state.page === 0;
      next.disabled = state.page >= pages - 1;
      info.textContent = `${shown.length} of ${rows.length} rows` + (paged ? `, page ${state.page + 1} of ${pages}` : '');
    }
    Array.from(table.tHead.rows[0].cells).forEach((th, c) => {
      th.classList.add('fspm-sortable');
      th.title = 'sort';
      th.addEventListener('click', () => {
        state.dir = state.col === c ? -state.dir : 1;
        state.col = c;
        table.tHead.querySelectorAll('th').forEach((h) => h.removeAttribute('aria-sort'));
        th.setAttribute('aria-sort', state.dir > 0 ? 'ascending' : 'descending');
        render();
      });
    });
    filter.addEventListener('input', () => { state.filter = filter.value.toLowerCase(); state.page = 0; render(); });
    prev.addEventListener('click', () => { state.page--; render(); });
    next.addEventListener('click', () => { state.page++; render(); });
    render();
  }

  // ---------- plots (drawn when they come into view) ----------
  const pending = [];
  const observer = 'IntersectionObserver' in window
    ? new IntersectionObserver((entries) => entries.forEach((e) => { if (e.isIntersecting) draw(e.target); }), { rootMargin: '300px' })
    : null;
  function lazy(div, drawFn) {
    div._fspmDraw = drawFn;
    pending.push(div);
    if (observer) observer.observe(div); else draw(div);
  }
  function draw(div) {
    if (!div._fspmDraw) return div._fspmDrawn;
    const f = div._fspmDraw;
    div._fspmDraw = null;
    if (observer) observer.unobserve(div);
    div._fspmDrawn = Promise.resolve(f(div));
    return div._fspmDrawn;
  }
  // Draws every plot and 3D view now (printing, tests).
  window.fspmDrawAll = () => Promise.all(pending.map(draw));

  // No tool bar (drag to zoom, double-click to zoom out): it would cover the titles.
  const kPlotConfig = { responsive: true, displayModeBar: false };
  function plot(div, traces, layout) {
    return Plotly.newPlot(div, traces, Object.assign({
      margin: { l: 60, r: 10, t: 36, b: 50 }, hovermode: 'closest', showlegend: false,
      font: { size: 11 },
    }, layout), kPlotConfig);
  }

  // Each metric against each swept parameter: every successful run a point, the mean per value a
  // line.
  function sweepPlots(host) {
    const ok = D.runs.status.map((s, i) => (s === 'ok' ? i : -1)).filter((i) => i >= 0);
    const age = D.swept.find((p) => (p === 'years' || p === 'age') && new Set(ok.map((i) => D.runs.parameters[p][i])).size >= 2);
    const ageValues = age ? [...new Set(ok.map((i) => D.runs.parameters[age][i]))].sort((a, b) => a - b) : [];
    for (const p of D.swept) {
      const values = D.runs.parameters[p];
      const distinct = [...new Set(ok.map((i) => values[i]))];
      if (distinct.length < 2) continue;
      const numeric = distinct.every((v) => typeof v === 'number');
      const order = numeric ? distinct.sort((a, b) => a - b) : distinct;
      host.appendChild(el('h3', { text: `Against ${p}` }));
      const grid = el('div', { class: 'fspm-grid' });
      host.appendChild(grid);
      for (const m of D.metrics.map((x) => x.name)) {
        const ys = D.runs.metrics[m];
        const pts = ok.filter((i) => ys[i] !== null && Number.isFinite(ys[i]));
        if (new Set(pts.map((i) => values[i])).size < 2) continue;
        const div = el('div', { class: 'fspm-plot fspm-sweep-plot', 'data-metric': m, 'data-parameter': p });
        grid.appendChild(div);
        lazy(div, () => {
          // Metrics grow with age: the means are per age, never pooled across ages; values of a
          // text parameter (presets, sets) are categories, so no line joins them.
          const ages = age && age !== p ? ageValues : [null];
          const meanTraces = ages.map((a, k) => {
            const means = order.map((v) => {
              const sel = pts.filter((i) => values[i] === v && (a === null || D.runs.parameters[age][i] === a)).map((i) => ys[i]);
              return sel.length ? sel.reduce((x, y) => x + y, 0) / sel.length : null;
            });
            const what = a === null ? `mean over ${p}` : `mean at ${age} = ${a}, ${p}`;
            return { type: 'scatter', mode: numeric ? 'lines+markers' : 'markers', x: order, y: means,
              name: a === null ? 'mean' : `${age} = ${a}`, marker: { size: 9, symbol: 'diamond' },
              line: a === null ? { color: '#d62728' } : undefined,
              hovertext: means.map((v, j) => `${what} = ${order[j]}: ${fmt(v)}`), hoverinfo: 'text' };
          });
          return plot(div, [
            { type: 'scatter', mode: 'markers', x: pts.map((i) => values[i]), y: pts.map((i) => ys[i]),
              name: 'runs', showlegend: false, marker: { size: 5, opacity: 0.45, color: '#7f7f7f' },
              hovertext: pts.map((i) => `${runText(D.runs.run[i])}<br>${escapeHtml(m)} = ${fmt(ys[i])}`),
              hoverinfo: 'text' },
            ...meanTraces,
          ], { title: { text: metricLabel(m) }, showlegend: ages.length > 1, legend: { orientation: 'h', y: -0.3 }, xaxis: { title: { text: p }, type: numeric ? 'linear' : 'category' },
            yaxis: { title: { text: metricInfo(m).unit || '' } } });
        });
      }
    }
  }

  // One box plot per comparison group, every pair a point.
  function boxPlots(host) {
    const P = D.pairs;
    const groups = [...new Set(P.group)];
    const grid = el('div', { class: 'fspm-grid' });
    host.appendChild(grid);
    for (const g of groups) {
      const div = el('div', { class: 'fspm-plot fspm-box-plot', 'data-group': g });
      grid.appendChild(div);
      lazy(div, () => {
        const traces = D.comparisons.map((c) => {
          const idx = P.comparison.map((x, i) => (x === c && P.group[i] === g ? i : -1)).filter((i) => i >= 0);
          const name = `${c} (n = ${idx.length})`;
          // Whiskers at the smallest and largest distance, as in report.md's figures: Plotly
          // draws them so for a box without points, and the points come as a second, lineless
          // box on top of it (layout.boxmode 'overlay').
          return [{ type: 'box', name, x: idx.map(() => name), y: idx.map((i) => P.distance[i]), boxpoints: false,
            hoverinfo: 'skip', showlegend: false, marker: { color: '#1f77b4' } },
          { type: 'box', name, x: idx.map(() => name), y: idx.map((i) => P.distance[i]), hoveron: 'points',
            boxpoints: 'all', jitter: 0.5, pointpos: 0, fillcolor: 'rgba(255,255,255,0)', line: { width: 0 }, marker: { size: 6, opacity: 0.75, color: '#1f77b4' },
            hovertext: idx.map((i) => (P.scale === 'raw' ? `pair of ${c}: distance ${fmt(P.distance[i])}<br>` : `pair of ${c}: normalized distance ${fmt(P.distance[i])} (raw ${fmt(P.raw_distance[i])})<br>`) +
              `<b>A</b> ${runText(P.run_a[i])}<br><b>B</b> ${runText(P.run_b[i])}`),
            hoverinfo: 'text+name', showlegend: false }];
        }).flat().filter((t) => t.y.length > 0);
        return plot(div, traces, { title: { text: g }, boxmode: 'overlay', yaxis: { title: { text: P.scale === 'raw' ? 'edit distance' : 'normalized edit distance' } } });
      });
    }
  }

  // Light against height in the crown, one line per typical tree (D.light_profiles, the numbers
  // of report.md's figure): light on the whole 0-1 range of the share of the open sky, so that
  // profiles compare across reports.
  function lightProfile(host) {
    const div = el('div', { class: 'fspm-plot fspm-light-plot' });
    const caption = el('figcaption', { text: 'Light: the mean over a layer\'s leaf clusters of the light their leaves receive, ' +
      'as a share of the open sky (0 = full shade, 1 = the whole sky unobstructed); height in m above the tree\'s base.' });
    host.appendChild(el('figure', { class: 'fspm-light-figure' }, [div, caption]));
    lazy(div, () => plot(div, D.light_profiles.map((t) => ({
      type: 'scatter', mode: 'lines+markers', name: `${escapeHtml(t.group)} (run ${t.run})`, x: t.mean_light, y: t.height_m,
      marker: { size: 7 },
      hovertext: t.height_m.map((h, j) => `run ${t.run} (${escapeHtml(t.group)})<br>height ${fmt(h)} m: light ${fmt(t.mean_light[j])} of the open sky<br>${t.clusters[j]} clusters`),
      hoverinfo: 'text',
    })), { title: { text: 'Light in the crown' }, showlegend: true, legend: { x: 1, xanchor: 'right', y: 1 },
      xaxis: { title: { text: 'mean light of the leaf clusters (share of the open sky)' }, range: [0, 1], dtick: 0.1, fixedrange: true, zeroline: false },
      yaxis: { title: { text: 'height above the base (m)' }, rangemode: 'tozero' } }));
  }

  // ---------- 3D trees ----------
  // One WebGL renderer for every view (browsers allow only a few WebGL contexts per page): it
  // draws a view offscreen and copies the picture into the view's own canvas.
  let renderer = null;
  function sharedRenderer() {
    if (!renderer) {
      renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
      renderer.setPixelRatio(window.devicePixelRatio || 1);
    }
    return renderer;
  }
  const glbWaiting = new Map();
  // Called by the trees/*.js files: a .glb, gzipped, in base64 (the browser's own
  // DecompressionStream inflates it).
  // A single-file report (fspm report --single-file) carries its trees inline: they arrive
  // before any view asks for them and wait here.
  const glbEmbedded = new Map();
  window.fspmGlb = (name, base64) => {
    const w = glbWaiting.get(name);
    if (!w) { glbEmbedded.set(name, base64); return; }
    const bytes = Uint8Array.from(atob(base64), (c) => c.charCodeAt(0));
    const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
    new Response(stream).arrayBuffer().then(w.resolve, w.reject);
  };
  function loadGlb(name) {
    if (!glbWaiting.has(name)) {
      let resolve, reject;
      const promise = new Promise((a, b) => { resolve = a; reject = b; });
      glbWaiting.set(name, { promise, resolve, reject });
      if (glbEmbedded.has(name)) {
        const base64 = glbEmbedded.get(name);
        glbEmbedded.delete(name);
        window.fspmGlb(name, base64);
        return promise;
      }
      const s = el('script', { src: `trees/${name}.js` });
      s.onerror = () => reject(new Error(`cannot load trees/${name}.js`));
      document.head.appendChild(s);
    }
    return glbWaiting.get(name).promise;
  }
  function parseGlb(buffer) {
    return new Promise((resolve, reject) => new THREE.GLTFLoader().parse(buffer.slice(0), '', resolve, reject));
  }

  // Viridis, 5 stops (matplotlib's), interpolated.
  const kViridis = [[0.267, 0.005, 0.329], [0.229, 0.322, 0.546], [0.128, 0.567, 0.551], [0.369, 0.789, 0.383], [0.993, 0.906, 0.144]];
  function viridis(t) {
    const x = Math.min(1, Math.max(0, t)) * (kViridis.length - 1);
    const k = Math.min(kViridis.length - 2, Math.floor(x));
    const f = x - k;
    return kViridis[k].map((c, j) => c + f * (kViridis[k + 1][j] - c));
  }
  const kBark = [0.45, 0.32, 0.20];  // nodes without a value keep the bark's colour, as the renders
  const isObstacle = (mesh) => /obstacle/.test(mesh.material.name || '');

  // Colours the tree (not the obstacles) by a vertex attribute, or restores the written materials.
  function colourBy(view, attribute) {
    let lo = Infinity, hi = -Infinity;
    view.meshes.forEach((m) => {
      const a = m.geometry.getAttribute(attribute);
      if (!a || isObstacle(m)) return;
      for (let i = 0; i < a.count; i++) {
        const v = a.getX(i);
        if (Number.isNaN(v)) continue;  // no value (e.g. light on a branch without a bud)
        lo = Math.min(lo, v); hi = Math.max(hi, v);
      }
    });
    view.meshes.forEach((m) => {
      const a = m.geometry.getAttribute(attribute);
      if (!attribute || !a || isObstacle(m)) { m.material = m.userData.written; return; }
      const colours = new Float32Array(3 * a.count);
      for (let i = 0; i < a.count; i++) {
        const v = a.getX(i);
        colours.set(Number.isNaN(v) ? kBark : viridis(hi > lo ? (v - lo) / (hi - lo) : 0.5), 3 * i);
      }
      m.geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
      // Flat shading: the trees come without normals (docs/experiments.md).
      m.material = new THREE.MeshStandardMaterial({ vertexColors: true, side: THREE.DoubleSide, roughness: 0.8, flatShading: true });
    });
    const name = attribute.replace(/^_/, '');
    view.legend.textContent = !attribute || lo > hi ? ''
      : lo === hi ? `${name}: ${fmt(lo)} everywhere`
        : `${name}: ${fmt(lo)} (dark violet) to ${fmt(hi)} (yellow)`;
    view.render();
  }

  // `shared` (optional): views framed alike, at the size of the largest of them, so that the two
  // trees of a pair compare in size.
  function treeView(host, run, caption, shared) {
    const canvas = el('canvas', { class: 'fspm-canvas', width: 380, height: 380 });
    const select = el('select', { class: 'fspm-colour' }, [el('option', { value: '', text: 'colours: bark, leaves, obstacles' })]);
    const legend = el('div', { class: 'fspm-legend' });
    const save = el('a', { text: 'download .glb', download: `run-${run}.glb`, href: '#' });
    const box = el('figure', { class: 'fspm-tree', 'data-run': run }, [canvas, el('div', { class: 'fspm-tree-bar' }, [select, save]), legend,
      el('figcaption', { text: caption })]);
    host.appendChild(box);
    lazy(box, async () => {
      const name = D.tree_files[run];
      const buffer = await loadGlb(name);
      save.href = URL.createObjectURL(new Blob([buffer], { type: 'model/gltf-binary' }));
      const gltf = await parseGlb(buffer);
      const scene = new THREE.Scene();
      scene.background = new THREE.Color(0xffffff);
      scene.add(new THREE.HemisphereLight(0xffffff, 0x666655, 2.2));
      const sun = new THREE.DirectionalLight(0xffffff, 1.6);
      sun.position.set(1, -1.5, 2);
      scene.add(sun);
      scene.add(gltf.scene);
      const meshes = [];
      gltf.scene.traverse((o) => { if (o.isMesh) { o.userData.written = o.material; meshes.push(o); } });
      const names = new Set();
      meshes.forEach((m) => Object.keys(m.geometry.attributes).filter((a) => a.startsWith('_')).forEach((a) => names.add(a)));
      names.forEach((a) => select.appendChild(el('option', { value: a, text: `colour by ${a.replace(/^_/, '')}` })));
      // Framed on the tree: the obstacles near it may reach far beyond.
      const bounds = new THREE.Box3();
      meshes.filter((m) => !isObstacle(m)).forEach((m) => bounds.expandByObject(m));
      if (bounds.isEmpty()) bounds.setFromObject(gltf.scene);
      const centre = bounds.getCenter(new THREE.Vector3());
      const extent = bounds.getSize(new THREE.Vector3());
      const size = extent.length() || 1;
      // The distance at which the box fills the view (height and width) with a margin.
      const tan = Math.tan(THREE.MathUtils.degToRad(35 / 2));
      const fit = 1.1 * Math.max(extent.z / 2 / tan, extent.x / 2 / (tan * canvas.width / canvas.height)) +
        extent.y / 2 || 1;
      const camera = new THREE.PerspectiveCamera(35, canvas.width / canvas.height, size / 1000, size * 100);
      camera.up.set(0, 0, 1); // fspm's trees grow along +z
      const controls = new THREE.OrbitControls(camera, canvas);
      const frame = (d) => {
        camera.position.copy(centre).add(new THREE.Vector3(0, -d, 0.2 * d));
        camera.far = d * 100;
        camera.updateProjectionMatrix();
        controls.target.copy(centre);
        controls.update();
      };
      frame(fit);
      const context = canvas.getContext('2d');
      const view = { meshes, legend, render() {
        const r = sharedRenderer();
        r.setSize(canvas.width, canvas.height, false);
        r.render(scene, camera);
        context.drawImage(r.domElement, 0, 0, canvas.width, canvas.height);
      } };
      controls.addEventListener('change', () => view.render());
      select.addEventListener('change', () => colourBy(view, select.value));
      view.render();
      if (shared) {
        shared.size = Math.max(shared.size || 0, fit);
        shared.frames.push(frame);
        shared.frames.forEach((f) => f(shared.size)); // each change renders its view
      }
    });
  }

  function treeViews(host) {
    const grid = el('div', { class: 'fspm-grid' });
    host.appendChild(grid);
    for (const t of D.trees) treeView(grid, t.run, t.caption);
  }

  function pairViews(host) {
    for (const p of D.pair_views) {
      host.appendChild(el('h4', { text: `${p.comparison}, ${p.group}: distance ${fmt(p.distance)}` }));
      const grid = el('div', { class: 'fspm-grid fspm-pair' });
      host.appendChild(grid);
      const shared = { frames: [] };
      treeView(grid, p.run_a, `A: ${runText(p.run_a).replace(/<br>/g, ', ')}`, shared);
      treeView(grid, p.run_b, `B: ${runText(p.run_b).replace(/<br>/g, ', ')}`, shared);
    }
  }

  // ---------- the page ----------
  function contents(main) {
    const list = el('ul');
    main.querySelectorAll('h2').forEach((h, i) => {
      h.id = h.id || `section-${i}`;
      list.appendChild(el('li', {}, [el('a', { href: `#${h.id}`, text: h.textContent })]));
    });
    return el('nav', { class: 'fspm-contents' }, [el('strong', { text: 'Contents' }), list]);
  }

  function main() {
    const content = document.getElementById('report');
    renderMarkdown(content);
    content.querySelectorAll('table').forEach(enhanceTable);
    const fill = { sweeps: sweepPlots, boxplots: boxPlots, trees: treeViews, pairs: pairViews, lightprofile: lightProfile };
    for (const [k, f] of Object.entries(fill)) content.querySelectorAll(`.fspm-${k}`).forEach((h) => f(h));
    const h1 = content.querySelector('h1');
    if (h1) h1.after(contents(content));
    document.title = D.title;
  }
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', main); else main();
})();
