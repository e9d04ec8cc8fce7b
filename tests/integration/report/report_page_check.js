// Test tool: opens a run's report.html in headless Chromium and prints what a reader sees, one
// fact per line, for tests/integration/report_test.sh to judge:
//   node report_page_check.js NODE_MODULES REPORT.html OUT_PREFIX T
//   section ID WIDTHxHEIGHT text=N ink=F   every section: its size, its text length, and the
//                                          share of its region of a full-page screenshot that
//                                          is not background (OUT_PREFIXpage.png)
//   prompt TEXT                            the prompt as the page shows it (text, not markup)
//   candidates N videos=V use=U            cards, embedded videos (data: URIs), "use" buttons
//   command NAME                           after "Use this one": the command shown for NAME,
//                                          written to OUT_PREFIXcmd_NAME.sh
//   seek T time=C paused=P label=L size=WxH  after moving the scrubber to T: the SVG's clock,
//                                          its pause state and the time shown; the animation
//                                          is screenshot to OUT_PREFIXseek.png
//   play paused=P advanced=A               after pressing Play: running, and its clock moves
//   links N outside=O missing=M            the outputs' download links: how many, how many
//                                          point outside the page's folder, how many name no
//                                          file there
//   link PATH BYTES                        each of them, with the size of the file it names
//   lottie frames=N shown=I want=J visible=V  the Lottie beside the SVG after seeking to T:
//                                          its frames, the one drawn inside its box, the one
//                                          for T, and how many are drawn (1); it is screenshot to
//                                          OUT_PREFIXlottie.png
//   addresses N data=D files=F unresolved=U  every href and src on the page: data: URIs, files
//                                          of the page's folder, and any other (none expected)
//   motion rows=N outlined=O verbs=V       the plan's rows, how many have their parts outlined
//                                          on the drawing, and their verbs
//   not_understood TEXT                    the words not understood, as the page names them
//   status TEXT                            the fit's status in the summary
//   user_colours N                         candidate frames drawn in the user's colours
//   keyframes folded=F rows=R              the keyframe table inside a closed <details>
// Chromium is /usr/bin/chromium (Debian's), or $CHROMIUM. Exit 2 on any failure, with one line.
'use strict';
const fs = require('fs');
const path = require('path');

const kSections = ['svgm-downloads', 'svgm-player', 'svgm-motion', 'svgm-input', 'svgm-candidates', 'svgm-compare', 'svgm-losses', 'svgm-timings'];

async function main() {
  const [modulesArg, report, prefix, tArg] = process.argv.slice(2);
  if (!tArg) throw new Error('usage: node report_page_check.js NODE_MODULES REPORT.html OUT_PREFIX T');
  const puppeteer = require(path.join(path.resolve(modulesArg), 'puppeteer-core'));
  const browser = await puppeteer.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--force-device-scale-factor=1', '--hide-scrollbars'],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 1100, height: 900, deviceScaleFactor: 1 });
    await page.goto('file://' + path.resolve(report), { waitUntil: 'load' });
    // Paused at 0 for the screenshot, so it does not depend on when it is taken.
    await page.evaluate(() => { const s = document.querySelector('#svgm-stage > svg'); s.pauseAnimations(); s.setCurrentTime(0); });
    const shot = await page.screenshot({ fullPage: true, encoding: 'base64' });
    fs.writeFileSync(`${prefix}page.png`, Buffer.from(shot, 'base64'));
    const rects = await page.evaluate((ids) => ids.map((id) => {
      const e = document.getElementById(id);
      if (!e) return { id, missing: true };
      const r = e.getBoundingClientRect();
      return { id, x: r.left + window.scrollX, y: r.top + window.scrollY, w: r.width, h: r.height,
               text: e.innerText.trim().length };
    }), kSections);
    // The screenshot decoded by a blank page's canvas: the share of each section's pixels that
    // differ from white by more than 48 levels in some channel.
    const blank = await browser.newPage();
    const ink = await blank.evaluate(async (png, rs) => {
      const img = new Image();
      img.src = 'data:image/png;base64,' + png;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width; c.height = img.height;
      const g = c.getContext('2d');
      g.drawImage(img, 0, 0);
      return rs.map((r) => {
        if (r.missing || r.w < 1 || r.h < 1) return 0;
        const d = g.getImageData(Math.round(r.x), Math.round(r.y), Math.round(r.w), Math.round(r.h)).data;
        let n = 0;
        for (let i = 0; i < d.length; i += 4)
          if (255 - d[i] > 48 || 255 - d[i + 1] > 48 || 255 - d[i + 2] > 48) ++n;
        return n / (d.length / 4);
      });
    }, shot, rects);
    await blank.close();
    rects.forEach((r, i) => {
      if (r.missing) console.log(`section ${r.id} missing`);
      else console.log(`section ${r.id} ${Math.round(r.w)}x${Math.round(r.h)} text=${r.text} ink=${ink[i].toFixed(4)}`);
    });
    console.log(`prompt ${await page.$eval('#svgm-prompt', (e) => e.textContent)}`);
    const cards = await page.$$eval('.svgm-candidate', (cs) => cs.map((c) => ({
      name: c.dataset.name,
      video: !!c.querySelector('video[src^="data:video/"]'),
      use: !!c.querySelector('.svgm-use'),
    })));
    console.log(`candidates ${cards.length} videos=${cards.filter((c) => c.video).length} use=${cards.filter((c) => c.use).length}`);
    for (const c of cards.filter((c) => c.use)) {
      const shown = await page.evaluate((name) => {
        const card = [...document.querySelectorAll('.svgm-candidate')].find((e) => e.dataset.name === name);
        const pre = card.querySelector('.svgm-cmd');
        const before = pre.hidden;
        card.querySelector('.svgm-use').click();
        return { before, after: pre.hidden, text: pre.textContent };
      }, c.name);
      if (!shown.before || shown.after) throw new Error(`"Use this one" of ${c.name} does not reveal its command`);
      fs.writeFileSync(`${prefix}cmd_${c.name}.sh`, shown.text + '\n');
      console.log(`command ${c.name}`);
    }
    // The scrubber, as a reader moves it: its value set, an input event.
    const t = Number(tArg);
    const seek = await page.evaluate(async (t) => {
      const svg = document.querySelector('#svgm-stage > svg');
      const scrub = document.getElementById('svgm-scrub');
      svg.unpauseAnimations();
      scrub.value = String(t);
      scrub.dispatchEvent(new Event('input', { bubbles: true }));
      await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
      const r = svg.getBoundingClientRect();
      return { time: svg.getCurrentTime(), paused: svg.animationsPaused(), label: document.getElementById('svgm-time').textContent,
               w: r.width, h: r.height };
    }, t);
    const svg = await page.$('#svgm-stage > svg');
    await svg.screenshot({ path: `${prefix}seek.png` });
    console.log(`seek ${t} time=${seek.time.toFixed(4)} paused=${seek.paused} label=${seek.label} size=${seek.w}x${seek.h}`);
    const lottie = await page.evaluate((t) => {
      const fig = document.getElementById('svgm-lottie');
      const imgs = fig ? [...fig.querySelectorAll('img')] : [];
      const dur = fig ? Number(fig.dataset.duration) : 0;
      // Drawn, not just unhidden: laid out with a size, inside the box that clips the frames.
      const box = fig ? fig.querySelector('.svgm-lottie-box').getBoundingClientRect() : null;
      const drawn = imgs.map((i) => {
        const r = i.getBoundingClientRect();
        return getComputedStyle(i).display !== 'none' && r.height > 0 && r.top >= box.top && r.bottom <= box.bottom + 1;
      });
      const shown = drawn.indexOf(true);
      const r = shown >= 0 ? imgs[shown].getBoundingClientRect() : null;
      return { n: imgs.length, shown, visible: drawn.filter((d) => d).length,
               clip: r ? { x: r.left + window.scrollX, y: r.top + window.scrollY, width: r.width, height: r.height } : null,
               want: dur > 0 ? Math.min(imgs.length - 1, Math.floor((t % dur) / dur * imgs.length)) : -1 };
    }, t);
    if (lottie.clip) await page.screenshot({ path: `${prefix}lottie.png`, clip: lottie.clip, captureBeyondViewport: true });
    console.log(`lottie frames=${lottie.n} shown=${lottie.shown} want=${lottie.want} visible=${lottie.visible}`);
    const play = await page.evaluate(async () => {
      const svg = document.querySelector('#svgm-stage > svg');
      const before = svg.getCurrentTime();
      document.getElementById('svgm-play').click();
      await new Promise((r) => setTimeout(r, 300));
      return { paused: svg.animationsPaused(), advanced: svg.getCurrentTime() > before };
    });
    console.log(`play paused=${play.paused} advanced=${play.advanced}`);
    // Download links resolve against the page's own address, as a click would.
    const links = await page.$$eval('#svgm-downloads a[href]', (as) => as.map((a) => a.href));
    const dir = path.dirname(path.resolve(report));
    let outside = 0, missing = 0;
    for (const href of links) {
      const u = new URL(href);
      const file = u.protocol === 'file:' ? decodeURIComponent(u.pathname) : '';
      if (!file || !file.startsWith(dir + path.sep)) { ++outside; continue; }
      if (!fs.existsSync(file) || !fs.statSync(file).isFile()) { ++missing; continue; }
      console.log(`link ${path.relative(dir, file)} ${fs.statSync(file).size}`);
    }
    console.log(`links ${links.length} outside=${outside} missing=${missing}`);
    // Every address on the page, not only the outputs': each is a data: URI or a file there.
    const every = await page.$$eval('[href],[src]', (es) => es.map((e) => e.getAttribute('href') ?? e.getAttribute('src')));
    let data = 0, files = 0, bad = 0;
    for (const a of every) {
      if (a.startsWith('data:')) { ++data; continue; }
      const file = decodeURIComponent(new URL(a, 'file://' + dir + '/').pathname);
      if (file.startsWith(dir + path.sep) && fs.existsSync(file) && fs.statSync(file).isFile()) ++files;
      else ++bad;
    }
    console.log(`addresses ${every.length} data=${data} files=${files} unresolved=${bad}`);
    // The motion: the plan's rows, each action's parts outlined on the drawing (drawn with a
    // size), the words not understood, and the fit's status as shown.
    const motion = await page.evaluate(() => {
      const rows = [...document.querySelectorAll('#svgm-motion tr.svgm-action')];
      const outlines = [...document.querySelectorAll('#svgm-motion .svgm-outline')];
      const drawn = outlines.filter((o) => { const r = o.getBoundingClientRect(); return r.width > 2 && r.height > 2; });
      const actions = new Set(drawn.map((o) => o.dataset.action));
      const nu = document.getElementById('svgm-not-understood');
      return { rows: rows.length, outlined: rows.filter((r) => actions.has(r.dataset.action)).length,
               verbs: rows.map((r) => r.cells[1].firstChild.textContent).join(','), unknown: nu ? nu.firstChild.textContent : '',
               status: document.querySelector('#svgm-summary b').textContent };
    });
    console.log(`motion rows=${motion.rows} outlined=${motion.outlined} verbs=${motion.verbs}`);
    console.log(`not_understood ${motion.unknown}`);
    console.log(`status ${motion.status}`);
    console.log(`user_colours ${await page.$$eval('.svgm-frames img[alt$="in your colours"]', (i) => i.length)}`);
    const keys = await page.evaluate(() => {
      const d = document.getElementById('svgm-keyframes');
      return { folded: !!d && !d.open, rows: d ? d.querySelectorAll('table.svgm-keys tr').length - 1 : 0 };
    });
    console.log(`keyframes folded=${keys.folded} rows=${keys.rows}`);
  } finally {
    await browser.close();
  }
}

main().catch((e) => {
  console.error(`report_page_check: ${String(e.message || e).split('\n')[0]}`);
  process.exit(2);
});
