// Test tool: opens report.html pages made from hostile animations (tests/data/hostile) in
// headless Chromium, does what a reader might (waits, clicks every link in the animation) and
// prints everything the page did, one fact per line, for report_hostile_test.sh to judge:
//   node hostile_page_check.js NODE_MODULES NAME=REPORT.html ...
//   dialog NAME TEXT          an alert/confirm/prompt opened (dismissed)
//   console NAME TYPE TEXT    a console message (script output, refused loads)
//   request NAME URL          a request other than the page itself and its data: URIs
//   navigated NAME URL        the page (main frame) went somewhere else
//   svg NAME count=N paths=P animations=A player=B   the inlined animation in the DOM; B: the
//                             page's own script ran (its Content-Security-Policy let it)
//   overlay NAME clear|covered  whether the drawing paints over the page outside its box (the
//                             Play button and the input section are what is hit there)
//   tree NAME same|differs|xml-error   the animation's markup parsed as XML (DOMParser) against
//                             the tree the page's HTML parser built from it
//   error NAME MESSAGE        the check of that page could not finish (it navigated away)
// Chromium is /usr/bin/chromium (Debian's), or $CHROMIUM. Exit 2 on any failure, with one line.
'use strict';
const fs = require('fs');
const path = require('path');

// How long the page is left to itself after loading, and after the clicks: a meta refresh of 0
// s, SMIL begun at 0 s and a javascript: URL all act within a frame or two.
const kSettleMs = 250;
// Pages checked at once in the one browser (each mostly waits).
const kParallel = 3;

async function check(page, name, file) {
  const url = 'file://' + path.resolve(file);
  page.on('dialog', async (d) => {
    console.log(`dialog ${name} ${d.message()}`);
    await d.dismiss().catch(() => {});
  });
  page.on('console', (m) => console.log(`console ${name} ${m.type()} ${m.text().split('\n')[0]}`));
  page.on('request', (r) => {
    if (r.url() !== url && !r.url().startsWith('data:')) console.log(`request ${name} ${r.url()}`);
  });
  page.on('framenavigated', (f) => {
    if (f === page.mainFrame() && f.url() !== url) console.log(`navigated ${name} ${f.url()}`);
  });
  await page.goto(url, { waitUntil: 'load' });
  await new Promise((r) => setTimeout(r, kSettleMs));
  // A reader clicks the drawing: links in it (javascript:, SMIL-set hrefs) act then.
  for (const a of await page.$$('#svgm-stage a')) {
    const box = await a.boundingBox().catch(() => null);
    if (box && box.width > 0 && box.height > 0) await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2).catch(() => {});
  }
  await new Promise((r) => setTimeout(r, kSettleMs));
  if (page.url() !== url) {  // navigated away: what is left to look at is not the report
    console.log(`svg ${name} count=0 paths=0 animations=0 player=false`);
    return;
  }
  const svg = await page.evaluate(() => ({
    count: document.querySelectorAll('#svgm-stage > svg').length,
    paths: document.querySelectorAll('#svgm-stage > svg path').length,
    animations: document.querySelectorAll('#svgm-stage > svg animate, #svgm-stage > svg animateTransform').length,
    player: typeof window.svgmSeek === 'function',
  }));
  console.log(`svg ${name} count=${svg.count} paths=${svg.paths} animations=${svg.animations} player=${svg.player}`);
  const covered = await page.evaluate(() => {
    const stage = document.getElementById('svgm-stage');
    return ['svgm-play', 'svgm-input'].some((id) => {
      const e = document.getElementById(id);
      e.scrollIntoView({ block: 'center' });  // elementFromPoint sees the viewport only
      const r = e.getBoundingClientRect();
      const hit = document.elementFromPoint(r.left + Math.min(r.width / 2, 20), r.top + Math.min(r.height / 2, 20));
      return !hit || stage.contains(hit);
    });
  });
  console.log(`overlay ${name} ${covered ? 'covered' : 'clear'}`);
  const html = fs.readFileSync(file, 'utf8');
  // The stage is followed by its caption (the Lottie beside it, then the controls).
  const m = /<div id="svgm-stage"[^>]*>([\s\S]*?)<\/div><figcaption>/.exec(html);
  const tree = await page.evaluate((markup) => {
    const dump = (n) => {
      if (n.nodeType === Node.TEXT_NODE) return 'T' + JSON.stringify(n.data);
      if (n.nodeType !== Node.ELEMENT_NODE) return 'N' + n.nodeType;
      const attrs = [...n.attributes].map((a) => `${a.namespaceURI || ''}|${a.localName}=${JSON.stringify(a.value)}`).sort();
      return `<${n.namespaceURI}|${n.localName} ${attrs.join(' ')}>${[...n.childNodes].map(dump).join('')}</>`;
    };
    const xml = new DOMParser().parseFromString(markup, 'image/svg+xml');
    if (xml.getElementsByTagName('parsererror').length) return 'xml-error';
    const stage = document.getElementById('svgm-stage');
    return [...stage.childNodes].map(dump).join('') === dump(xml.documentElement) ? 'same' : 'differs';
  }, m ? m[1] : '');
  console.log(`tree ${name} ${tree}`);
}

async function main() {
  const [modulesArg, ...pages] = process.argv.slice(2);
  if (!pages.length) throw new Error('usage: node hostile_page_check.js NODE_MODULES NAME=REPORT.html ...');
  const puppeteer = require(path.join(path.resolve(modulesArg), 'puppeteer-core'));
  const browser = await puppeteer.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
           '--disable-component-update', '--disable-sync'],
  });
  try {
    const queue = [...pages];
    const worker = async () => {
      for (let p = queue.shift(); p; p = queue.shift()) {
        const eq = p.indexOf('='), name = p.slice(0, eq);
        const page = await browser.newPage();
        // A page that navigated away mid-check has said so (navigated ...); the others go on.
        await check(page, name, p.slice(eq + 1)).catch((e) => console.log(`error ${name} ${String(e.message || e).split('\n')[0]}`));
        await page.close().catch(() => {});
      }
    };
    await Promise.all(Array.from({ length: kParallel }, worker));
  } finally {
    await browser.close();
  }
}

main().catch((e) => {
  console.error(`hostile_page_check: ${String(e.message || e).split('\n')[0]}`);
  process.exit(2);
});
