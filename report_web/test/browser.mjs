// Headless Chromium for the report's browser tests: Debian's chromium (or $CHROMIUM), with
// WebGL through SwiftShader, Chromium's software renderer, since test machines have no GPU.
import puppeteer from 'puppeteer-core';

export function launchBrowser() {
  return puppeteer.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-dev-shm-usage'],
  });
}
