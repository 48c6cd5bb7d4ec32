// Opens an HTML report of `fspm report --html` from file:// in headless Chromium and checks it as
// a reader would see it: no console error, every plot and 3D view drawn (their screenshots not
// blank), a header click sorts a table, the light profile plot shows data.js's numbers where they
// lie on its axes. Writes a screenshot of the page top and the page's tables (every row, all
// pages) as JSON for check_numbers.py.
//   node check_report.mjs REPORT/index.html SCREENSHOT.png TABLES.json
import { launchBrowser } from './browser.mjs';
import fs from 'node:fs';
import path from 'node:path';

const [indexPath, screenshotPath, tablesPath] = process.argv.slice(2);
if (!tablesPath) {
  console.error('usage: node check_report.mjs REPORT/index.html SCREENSHOT.png TABLES.json');
  process.exit(2);
}
const failures = [];
const fail = (what) => { failures.push(what); console.error(`FAIL: ${what}`); };

const browser = await launchBrowser();
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 900 });
  page.on('console', (m) => { if (m.type() === 'error') fail(`console error: ${m.text()}`); });
  page.on('pageerror', (e) => fail(`page error: ${e.message}`));
  page.on('requestfailed', (r) => fail(`request failed: ${r.url()} ${r.failure()?.errorText}`));
  await page.goto('file://' + path.resolve(indexPath), { waitUntil: 'load', timeout: 120000 });
  await page.waitForFunction(() => typeof window.fspmDrawAll === 'function', { timeout: 60000 });
  await page.evaluate(() => window.fspmDrawAll());

  // The share of a screenshot's pixels that are not (near) white, or with `colourful` the share
  // of clearly coloured ones (max - min channel > 40), measured in the page itself.
  async function inkShare(handle, colourful = false) {
    const png = await handle.screenshot({ encoding: 'base64' });
    return page.evaluate(async (data, colourful) => {
      const img = new Image();
      img.src = 'data:image/png;base64,' + data;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width; c.height = img.height;
      const g = c.getContext('2d');
      g.drawImage(img, 0, 0);
      const px = g.getImageData(0, 0, c.width, c.height).data;
      let ink = 0;
      for (let i = 0; i < px.length; i += 4) {
        const [r, g, b] = [px[i], px[i + 1], px[i + 2]];
        if (colourful ? Math.max(r, g, b) - Math.min(r, g, b) > 40 : r + g + b < 3 * 235) ink++;
      }
      return ink / (px.length / 4);
    }, png, colourful);
  }

  const plots = await page.$$('.fspm-plot');
  const views = await page.$$('canvas.fspm-canvas');
  if (plots.length === 0) fail('no plots on the page');
  if (views.length === 0) fail('no 3D views on the page');
  for (const [i, p] of plots.entries()) {
    await p.scrollIntoView();
    const marks = await p.evaluate((e) => e.querySelectorAll('.scatterlayer .point, .boxlayer .box, .boxlayer .point').length);
    const share = await inkShare(p);
    if (marks === 0 || share < 0.01) fail(`plot ${i} looks empty (${marks} marks, ${(100 * share).toFixed(2)} % ink)`);
  }
  for (const [i, v] of views.entries()) {
    await v.scrollIntoView();
    // Even a leafless L-system tree covers more than a sliver of its view; a blank one is white.
    const share = await inkShare(v);
    if (share < 0.005) fail(`3D view ${i} looks blank (${(100 * share).toFixed(2)} % ink)`);
  }

  // Colouring by an attribute (order: it varies in every branched tree) repaints the first view.
  if (views.length > 0) {
    const before = await views[0].screenshot({ encoding: 'base64' });
    const ink = await inkShare(views[0]);
    const attribute = await page.evaluate(() => {
      const select = document.querySelector('.fspm-tree select');
      const options = Array.from(select.options);
      const option = options.find((o) => o.value === '_order') || options.find((o) => o.value);
      if (!option) return null;
      select.value = option.value;
      select.dispatchEvent(new Event('change'));
      return option.value;
    });
    if (!attribute) fail('no attribute to colour the first tree by');
    else if ((await views[0].screenshot({ encoding: 'base64' })) === before) fail(`colouring by ${attribute} changed nothing`);
    else if ((await inkShare(views[0], true)) < 0.2 * ink) fail(`colouring by ${attribute} left the tree without colours`);
  }

  // Sorting: a click on a numeric column's header puts its rows in order, and changes the order.
  const sorted = await page.evaluate(() => {
    for (const table of document.querySelectorAll('#report table')) {
      const rows = () => Array.from(table.tBodies[0].rows);
      if (rows().length < 3) continue;
      const ths = Array.from(table.tHead.rows[0].cells);
      for (let c = 0; c < ths.length; c++) {
        const num = (r) => parseFloat(r.cells[c].textContent);
        const before = rows().map(num);
        if (before.some(isNaN) || new Set(before).size < 3) continue;
        ths[c].click(); // ascending
        ths[c].click(); // descending
        const after = rows().map(num);
        const ordered = after.every((v, i) => i === 0 || after[i - 1] >= v);
        return { header: ths[c].textContent, changed: before.join() !== after.join(), ordered };
      }
    }
    return null;
  });
  if (!sorted) fail('no table with a numeric column to sort');
  else if (!sorted.changed || !sorted.ordered) fail(`sorting by "${sorted.header}" did not order the rows: ${JSON.stringify(sorted)}`);

  // The light profile: one line per tree of data.js's light_profiles (read here from the file
  // fspm wrote, not from the page), its values those of the data, and its points drawn where
  // those values lie on the axes (light on the fixed 0-1 axis of the share of the open sky).
  const dataText = fs.readFileSync(path.join(path.dirname(indexPath), 'data.js'), 'utf8');
  const written = JSON.parse(dataText.replace(/^window\.FSPM_REPORT = /, '').replace(/;\s*$/, ''));
  const profiles = written.light_profiles || [];
  if (profiles.length === 0) fail('data.js has no light profile (the check\'s trees have leaf clusters)');
  const light = await page.evaluate(() => {
    const divs = document.querySelectorAll('.fspm-light-plot');
    if (divs.length !== 1) return { count: divs.length };
    const gd = divs[0];
    const xa = gd._fullLayout.xaxis, ya = gd._fullLayout.yaxis;
    const traces = Array.from(gd.querySelectorAll('.scatterlayer .trace')).map((t) =>
      Array.from(t.querySelectorAll('.points .point')).map((p) => {
        const m = /translate\(([-\d.e]+),\s*([-\d.e]+)\)/.exec(p.getAttribute('transform'));
        return [xa.p2c(parseFloat(m[1])), ya.p2c(parseFloat(m[2]))];
      }));
    return {
      count: 1,
      data: gd.data.map((t) => ({ name: t.name, x: Array.from(t.x), y: Array.from(t.y) })),
      drawn: traces,
      xRange: xa.range, xTitle: xa.title.text, yTitle: ya.title.text,
      xPerPixel: (xa.range[1] - xa.range[0]) / xa._length, yPerPixel: (ya.range[1] - ya.range[0]) / ya._length,
      caption: gd.closest('figure')?.querySelector('figcaption')?.textContent || '',
    };
  });
  if (profiles.length > 0) {
    if (light.count !== 1) fail(`${light.count} light profile plots on the page, expected 1`);
    else {
      if (light.data.length !== profiles.length) fail(`light profile: ${light.data.length} lines, data.js has ${profiles.length} trees`);
      if (light.xRange[0] !== 0 || light.xRange[1] !== 1) fail(`light profile: light axis ${light.xRange}, expected 0 to 1`);
      if (!/share of the open sky/.test(light.xTitle)) fail(`light profile: light axis titled "${light.xTitle}"`);
      if (!/\(m\)/.test(light.yTitle)) fail(`light profile: height axis titled "${light.yTitle}"`);
      if (!/share of the open sky/.test(light.caption)) fail(`light profile: caption "${light.caption}" does not say what the light is`);
      profiles.forEach((t, k) => {
        const d = light.data[k];
        if (!d) return;
        if (d.name !== `${t.group} (run ${t.run})`) fail(`light profile line ${k}: "${d.name}", data.js ${t.group} (run ${t.run})`);
        if (JSON.stringify(d.x) !== JSON.stringify(t.mean_light)) fail(`light profile run ${t.run}: light ${d.x} on the page, ${t.mean_light} in data.js`);
        if (JSON.stringify(d.y) !== JSON.stringify(t.height_m)) fail(`light profile run ${t.run}: height ${d.y} on the page, ${t.height_m} in data.js`);
        const drawn = light.drawn[k] || [];
        if (drawn.length !== t.mean_light.length) fail(`light profile run ${t.run}: ${drawn.length} points drawn, ${t.mean_light.length} layers in data.js`);
        drawn.forEach(([x, y], j) => {
          // Within a pixel and a half of where the data puts them.
          if (Math.abs(x - t.mean_light[j]) > 1.5 * light.xPerPixel || Math.abs(y - t.height_m[j]) > 1.5 * light.yPerPixel)
            fail(`light profile run ${t.run}, layer ${j}: drawn at (${x}, ${y}), data.js (${t.mean_light[j]}, ${t.height_m[j]})`);
        });
      });
    }
  }

  // Every table, every row (the page keeps the rows of all pages), with the heading above it.
  const tables = await page.evaluate(() => Array.from(document.querySelectorAll('#report table')).map((t) => {
    let h = t.closest('.fspm-table-wrap') || t;
    while (h && !/^H[1-4]$/.test(h.tagName)) h = h.previousElementSibling;
    return {
      heading: h ? h.textContent : '',
      headers: Array.from(t.tHead.rows[0].cells).map((c) => c.textContent.replace(/ [▲▼]$/, '')),
      rows: t._fspmRows.map((r) => Array.from(r.cells).map((c) => c.textContent)),
    };
  }));
  fs.writeFileSync(tablesPath, JSON.stringify(tables, null, 1));

  // The page's top, and the page at the box plots, the sweeps, the trees and the pairs
  // (SHOT-plots.png, SHOT-sweeps.png, SHOT-trees.png, SHOT-pairs.png,
  // SHOT-light.png), as a reader sees them.
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: screenshotPath });
  for (const [what, selector] of [['plots', '.fspm-boxplots'], ['sweeps', '.fspm-sweeps'], ['trees', '.fspm-trees'], ['pairs', '.fspm-pairs'], ['light', '.fspm-light-figure']]) {
    const found = await page.evaluate((sel) => {
      const e = document.querySelector(sel);
      if (!e) return false;
      window.scrollTo(0, e.getBoundingClientRect().top + window.scrollY - 120);
      return true;
    }, selector);
    if (found) await page.screenshot({ path: screenshotPath.replace(/\.png$/, `-${what}.png`) });
  }
  console.log(`checked ${profiles.length} light profiles, ${plots.length} plots, ${views.length} 3D views, ${tables.length} tables; sorted by "${sorted?.header}"`);
} finally {
  await browser.close();
}
if (failures.length) {
  console.error(`${failures.length} failures`);
  process.exit(1);
}
