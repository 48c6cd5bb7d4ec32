// How long an HTML report of `fspm report --html` takes to open from file:// in headless
// Chromium: navigation to the load event, and to the first screen drawn (the plots and 3D views
// in view, which the page draws lazily). Prints JSON; run several times and take the median.
//   node time_open.mjs REPORT/index.html
import { launchBrowser } from './browser.mjs';
import path from 'node:path';

const [indexPath] = process.argv.slice(2);
if (!indexPath) {
  console.error('usage: node time_open.mjs REPORT/index.html');
  process.exit(2);
}
const browser = await launchBrowser();
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 900 });
  const t0 = Date.now();
  await page.goto('file://' + path.resolve(indexPath), { waitUntil: 'load', timeout: 120000 });
  const load = (Date.now() - t0) / 1000;
  // The first screen is drawn when every lazily drawn plot or 3D view within it has been drawn
  // (the page keeps each one's drawing promise on the element).
  await page.evaluate(async () => {
    const lazy = () => [...document.querySelectorAll('div')].filter(
      (e) => ('_fspmDraw' in e) && e.getBoundingClientRect().top < window.innerHeight);
    for (let i = 0; i < 2400 && lazy().some((e) => e._fspmDraw); ++i) {
      await new Promise((r) => setTimeout(r, 50));
    }
    await Promise.all(lazy().map((e) => e._fspmDrawn));
  });
  const firstScreen = (Date.now() - t0) / 1000;
  console.log(JSON.stringify({ load_seconds: load, first_screen_seconds: firstScreen }));
} finally {
  await browser.close();
}
