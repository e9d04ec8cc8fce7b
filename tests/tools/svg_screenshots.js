// Test tool: headless Chromium's rendering of SVG files, one CSS pixel per image pixel.
//   node svg_screenshots.js NODE_MODULES OUT_SUFFIX X.svg...
// writes X<OUT_SUFFIX> (e.g. X.chromium.png) for each X.svg: the SVG as an <img> of its own
// width x height on a white page, in one browser (a fresh Chromium per file costs ~15 s).
// Chromium is /usr/bin/chromium (Debian's), or $CHROMIUM. Exit 2 on any failure, with one line.
'use strict';
const fs = require('fs');
const path = require('path');

async function main() {
  const [modulesArg, suffix, ...svgs] = process.argv.slice(2);
  if (!svgs.length) throw new Error('usage: node svg_screenshots.js NODE_MODULES OUT_SUFFIX X.svg...');
  const puppeteer = require(path.join(path.resolve(modulesArg), 'puppeteer-core'));
  const browser = await puppeteer.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--force-device-scale-factor=1', '--hide-scrollbars'],
  });
  try {
    const page = await browser.newPage();
    for (const svg of svgs) {
      const text = fs.readFileSync(svg, 'utf8');
      const w = Number(/<svg[^>]*\swidth="([\d.]+)"/.exec(text)[1]);
      const h = Number(/<svg[^>]*\sheight="([\d.]+)"/.exec(text)[1]);
      await page.setViewport({ width: w, height: h, deviceScaleFactor: 1 });
      const data = 'data:image/svg+xml;base64,' + Buffer.from(text).toString('base64');
      await page.setContent(`<!doctype html><html><body style="margin:0;background:#fff">
        <img id="i" style="display:block" width="${w}" height="${h}" src="${data}"></body></html>`);
      await page.evaluate(() => document.getElementById('i').decode());
      const out = svg.replace(/\.svg$/, '') + suffix;
      await page.screenshot({ path: out, clip: { x: 0, y: 0, width: w, height: h } });
    }
  } finally {
    await browser.close();
  }
}

main().catch((e) => {
  console.error(`svg_screenshots: ${String(e.message || e).split('\n')[0]}`);
  process.exit(2);
});
