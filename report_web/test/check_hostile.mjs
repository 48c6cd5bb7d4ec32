// Opens the HTML report of an experiment whose every user-written field (name, description, names
// of comparisons) carries script (javascript: and data: links, event-handler attributes, raw HTML,
// entity-encoded schemes) and checks that none of it runs or stays live: no dialog, no page error,
// the flag the payloads would set stays unset, no link or image outside http(s):, mailto: and
// relative paths, no on* attribute, no <script> but the page's own; the safe links stay live and
// the hostile ones are shown as text.
//   node check_hostile.mjs REPORT/index.html
import { launchBrowser } from './browser.mjs';
import path from 'node:path';

const [indexPath] = process.argv.slice(2);
if (!indexPath) {
  console.error('usage: node check_hostile.mjs REPORT/index.html');
  process.exit(2);
}
const failures = [];
const fail = (what) => { failures.push(what); console.error(`FAIL: ${what}`); };

const browser = await launchBrowser();
try {
  const page = await browser.newPage();
  page.on('dialog', async (d) => { fail(`a dialog opened: ${d.message()}`); await d.dismiss(); });
  page.on('pageerror', (e) => fail(`page error: ${e.message}`));
  await page.goto('file://' + path.resolve(indexPath), { waitUntil: 'load', timeout: 120000 });
  await page.waitForFunction(() => typeof window.fspmDrawAll === 'function', { timeout: 60000 });
  await page.evaluate(() => window.fspmDrawAll());
  // Give any image error handler or timer the payloads could have planted the time to fire.
  await new Promise((r) => setTimeout(r, 1500));
  const found = await page.evaluate(() => {
    const safe = /^(https?:|mailto:)/i;
    const relative = (u) => { try { return new URL(u, 'fspm-relative:/').protocol === 'fspm-relative:'; } catch (e) { return false; } };
    const bad = [];
    for (const e of document.querySelectorAll('*')) {
      for (const a of e.attributes) {
        const name = a.name.toLowerCase();
        if (name.startsWith('on')) bad.push(`${e.tagName} ${name}="${a.value}"`);
        // The page's own "download .glb" links point at blobs it made itself.
        const ownBlob = e.hasAttribute('download') && a.value.startsWith('blob:');
        if (['href', 'src', 'xlink:href', 'action', 'formaction'].includes(name) && !safe.test(a.value.trim()) && !relative(a.value) && !ownBlob) {
          bad.push(`${e.tagName} ${name}="${a.value}"`);
        }
      }
    }
    const scripts = Array.from(document.scripts).map((s) => s.getAttribute('src') || 'inline');
    const report = document.getElementById('report');
    const links = Array.from(report.querySelectorAll('a[href]')).map((a) => a.getAttribute('href'));
    return { pwned: window.__fspmPwned === 1, bad, scripts, links, text: report.textContent };
  });
  if (found.pwned) fail('a payload ran (window.__fspmPwned is set)');
  for (const b of found.bad) fail(`unsafe attribute: ${b}`);
  const own = ['lib/marked.min.js', 'lib/safe_markdown.js', 'lib/plotly.min.js', 'lib/three.min.js', 'data.js', 'lib/report.js'];
  for (const s of found.scripts) {
    if (!own.includes(s) && !/^trees\/[^/]+\.js$/.test(s)) fail(`a script that is not the page's own: ${s}`);
  }
  // The harmless links are live, the hostile ones are text the reader can see.
  for (const live of ['https://example.org/ok', 'mailto:someone@example.org', 'notes/relative.md']) {
    if (!found.links.includes(live)) fail(`the safe link ${live} is not live (links: ${found.links.join(', ')})`);
  }
  for (const shown of ['js-link [javascript:window.__fspmPwned=1]', 'data-link [data:text/html', 'onerror=']) {
    if (!found.text.includes(shown)) fail(`"${shown}" is not shown as text`);
  }
  console.log(`checked ${found.links.length} live links, ${found.scripts.length} scripts; ${failures.length} failures`);
} finally {
  await browser.close();
}
if (failures.length) process.exit(1);
