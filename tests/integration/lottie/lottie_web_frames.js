// Test tool: frames of a Lottie file drawn by lottie-web (Airbnb's player) in headless
// Chromium, the player the web uses.
//   node lottie_web_frames.js NODE_MODULES ANIMATION.json WIDTH HEIGHT OUT_PREFIX svg|canvas FRAME...
// writes OUT_PREFIX<i>.png for the i-th FRAME (a frame number of the Lottie timeline): the
// animation in a WIDTH x HEIGHT box on a white page, one CSS pixel per image pixel.
// Chromium is /usr/bin/chromium (Debian's), or $CHROMIUM. Exit 2 on any failure, with one line.
'use strict';
const fs = require('fs');
const path = require('path');

async function main() {
  const [modulesArg, animation, w, h, prefix, renderer, ...frames] = process.argv.slice(2);
  if (!frames.length || !['svg', 'canvas'].includes(renderer)) {
    throw new Error('usage: node lottie_web_frames.js NODE_MODULES ANIMATION.json WIDTH HEIGHT OUT_PREFIX svg|canvas FRAME...');
  }
  const width = Number(w), height = Number(h);
  const nodeModules = path.resolve(modulesArg || '.');
  const puppeteer = require(path.join(nodeModules, 'puppeteer-core'));
  const player = path.join(nodeModules, 'lottie-web', 'build', 'player', 'lottie.min.js');
  const data = JSON.parse(fs.readFileSync(animation, 'utf8'));
  const browser = await puppeteer.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    // Root in CI: Chromium's sandbox needs a user namespace it may not get there.
    args: ['--no-sandbox', '--disable-gpu', '--force-device-scale-factor=1', '--hide-scrollbars'],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({ width, height, deviceScaleFactor: 1 });
    await page.setContent(`<!doctype html><html><body style="margin:0;background:#fff">
      <div id="a" style="width:${width}px;height:${height}px"></div></body></html>`);
    await page.addScriptTag({ path: player });
    await page.evaluate((d, r) => new Promise((resolve) => {
      window.anim = lottie.loadAnimation({
        container: document.getElementById('a'), renderer: r, loop: false, autoplay: false, animationData: d,
      });
      if (window.anim.isLoaded) resolve(); else window.anim.addEventListener('DOMLoaded', resolve);
    }), data, renderer);
    for (let i = 0; i < frames.length; ++i) {
      await page.evaluate((f) => window.anim.goToAndStop(f, true), Number(frames[i]));
      await page.screenshot({ path: `${prefix}${i}.png`, clip: { x: 0, y: 0, width, height } });
    }
  } finally {
    await browser.close();
  }
}

main().catch((e) => {
  console.error(`lottie_web_frames: ${String(e.message || e).split('\n')[0]}`);
  process.exit(2);
});
