// Test tool: frames of a .lottie (or Lottie JSON) file drawn by dotlottie-web (LottieFiles'
// player: ThorVG compiled to WebAssembly, drawing into a canvas) in headless Chromium.
//   node dotlottie_web_frames.js NODE_MODULES ANIMATION.lottie|.json WIDTH HEIGHT OUT_PREFIX FRAME...
// writes OUT_PREFIX<i>.png for the i-th FRAME (a frame number of the Lottie timeline): the
// animation in a WIDTH x HEIGHT canvas on a white page, one CSS pixel per image pixel. The
// player, its WebAssembly and the file are served from a local HTTP server on 127.0.0.1 (the
// player fetches its .wasm; nothing leaves the machine). Chromium is /usr/bin/chromium, or
// $CHROMIUM. Exit 2 on any failure, with one line.
'use strict';
const fs = require('fs');
const http = require('http');
const path = require('path');

function serve(files) {
  const server = http.createServer((req, res) => {
    const f = files[req.url];
    if (!f) { res.writeHead(404); res.end(); return; }
    res.writeHead(200, { 'Content-Type': f.type });
    res.end(fs.readFileSync(f.path));
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(server)));
}

async function main() {
  const [modulesArg, animation, w, h, prefix, ...frames] = process.argv.slice(2);
  if (!frames.length) {
    throw new Error('usage: node dotlottie_web_frames.js NODE_MODULES ANIMATION.lottie|.json WIDTH HEIGHT OUT_PREFIX FRAME...');
  }
  const width = Number(w), height = Number(h);
  const nodeModules = path.resolve(modulesArg || '.');
  const puppeteer = require(path.join(nodeModules, 'puppeteer-core'));
  const dist = path.join(nodeModules, '@lottiefiles', 'dotlottie-web', 'dist');
  const isJson = animation.endsWith('.json');
  const server = await serve({
    '/': { path: null, type: 'text/html' },
    '/index.js': { path: path.join(dist, 'index.js'), type: 'text/javascript' },
    '/dotlottie-player.wasm': { path: path.join(dist, 'dotlottie-player.wasm'), type: 'application/wasm' },
    '/animation': { path: path.resolve(animation), type: isJson ? 'application/json' : 'application/zip' },
    '/page.html': { path: null, type: 'text/html' },
  });
  const base = `http://127.0.0.1:${server.address().port}`;
  const browser = await puppeteer.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    protocolTimeout: 60000,
    args: ['--no-sandbox', '--disable-gpu', '--force-device-scale-factor=1', '--hide-scrollbars'],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({ width, height, deviceScaleFactor: 1 });
    await page.goto(`${base}/index.js`);  // an origin for the module import and fetches
    await page.setContent(`<!doctype html><html><body style="margin:0;background:#fff">
      <canvas id="c" width="${width}" height="${height}" style="width:${width}px;height:${height}px;display:block"></canvas></body></html>`);
    await page.evaluate(async (b, json) => {
      const { DotLottie } = await import(`${b}/index.js`);
      DotLottie.setWasmUrl(`${b}/dotlottie-player.wasm`);
      const data = json ? await (await fetch(`${b}/animation`)).text() : await (await fetch(`${b}/animation`)).arrayBuffer();
      await new Promise((resolve, reject) => {
        window.player = new DotLottie({
          canvas: document.getElementById('c'), data, autoplay: false, loop: false,
          renderConfig: { devicePixelRatio: 1, autoResize: false, freezeOnOffscreen: false },
        });
        window.player.addEventListener('load', resolve);
        window.player.addEventListener('loadError', (e) => reject(new Error(`dotlottie-web cannot load: ${e.error}`)));
      });
    }, base, isJson);
    for (let i = 0; i < frames.length; ++i) {
      // setFrame draws synchronously into the canvas when the frame changes (no 'render' event
      // when it does not); two animation frames let the page composite it.
      await page.evaluate((f) => new Promise((resolve) => {
        window.player.setFrame(f);
        requestAnimationFrame(() => requestAnimationFrame(resolve));
      }), Number(frames[i]));
      await page.screenshot({ path: `${prefix}${i}.png`, clip: { x: 0, y: 0, width, height } });
    }
  } finally {
    await browser.close();
    server.close();
  }
}

main().catch((e) => {
  console.error(`dotlottie_web_frames: ${String(e.message || e).split('\n')[0]}`);
  process.exit(2);
});
