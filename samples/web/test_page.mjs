// The page in headless Chromium (Debian's /usr/bin/chromium, driven by playwright-core; no browser
// is downloaded): it loads, its agent learns cart-pole in the page, and a screenshot is taken.
// `node test_page.mjs [screenshot.png]`; CHROMIUM overrides the browser's path.
// Learning is measured inside the page: the mean seconds balanced over the last 20 of 500 trials against
// trials 1-20. Then the JS API in the page: the fixed-seed runs of bindings/web/test/fixed_runs.js
// give the same actions in Chromium as in Node.js, and as the native library when
// VERVE_NATIVE_PROGRAM names bindings/web/test/native/hot_plate_actions (scripts/test_web.sh does);
// the continuous actions of a fixed-seed 1-D reach (bindings/web/test/reach.js) are bit for bit
// Node.js's; a bad input is a VerveError there too.
import { execFileSync } from 'node:child_process';
import { chromium } from 'playwright-core';
import { loadVerve } from '../../bindings/web/src/index.js';
import { fixedRuns } from '../../bindings/web/test/fixed_runs.js';
import { reachRun } from '../../bindings/web/test/reach.js';
import { serve } from './serve.mjs';

const screenshot = process.argv[2] ?? 'web-cart-pole.png';
const TRIALS = 500;
const server = await serve(0);
const url = `http://127.0.0.1:${server.address().port}/samples/web/?speed=fast&seed=1`;
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
    '--disable-component-update', '--disable-sync'],
});
let failed = false;
const fail = (message) => {
  console.error(`FAIL: ${message}`);
  failed = true;
};
try {
  const page = await browser.newPage({ viewport: { width: 1290, height: 460 } });
  page.on('pageerror', (e) => fail(`page error: ${e.message}`));
  page.on('console', (m) => { if (m.type() === 'error') fail(`console error: ${m.text()}`); });
  const started = Date.now();
  await page.goto(url);
  await page.waitForFunction(() => window.verveDemo?.ready || window.verveDemo?.error, null, { timeout: 20000 });
  const error = await page.evaluate(() => window.verveDemo.error);
  if (error) throw new Error(`the page could not start: ${error}`);
  await page.waitForFunction((n) => window.verveDemo.trials >= n || window.verveDemo.error, TRIALS, { timeout: 90000, polling: 200 });
  const demo = await page.evaluate(() => ({ ...window.verveDemo, history: window.verveDemo.history.slice() }));
  if (demo.error) throw new Error(demo.error);
  const mean = (a) => a.reduce((x, y) => x + y, 0) / a.length;
  const early = mean(demo.history.slice(0, 20));
  const late = mean(demo.history.slice(TRIALS - 20, TRIALS));
  console.log(`page: Verve ${demo.version}, ${TRIALS} trials in ${((Date.now() - started) / 1000).toFixed(1)} s, ` +
    `${demo.stepsPerSecond} agent steps/s; seconds balanced: trials 1-20 ${early.toFixed(2)}, ` +
    `${TRIALS - 19}-${TRIALS} ${late.toFixed(2)}; ${demo.rbfs} RBFs`);
  if (!(late > 5 * early)) fail(`no clear learning: ${early.toFixed(2)} s -> ${late.toFixed(2)} s`);
  // The JS API inside the page, against Node.js and the native library.
  const browserRuns = await page.evaluate(async () => {
    const { loadVerve: load } = await import('/bindings/web/src/index.js');
    const { fixedRuns: runs } = await import('/bindings/web/test/fixed_runs.js');
    const { reachRun: reach } = await import('/bindings/web/test/reach.js');
    const verve = await load();
    let refusal = '';
    try {
      verve.createAgent({ actions: 2 }).update(NaN, null, 0.1);
    } catch (e) {
      refusal = `${e.name} ${e.code}`;
    }
    return { lines: runs(verve), refusal, reach: reach(verve) };
  });
  if (browserRuns.refusal !== 'VerveError VERVE_ERROR_INVALID_ARGUMENT') fail(`a NaN reward in the page gave '${browserRuns.refusal}'`);
  // Continuous actions: the same wasm in both engines; compared with Node.js only, since the
  // native library's tanh and exp are glibc's, not the wasm build's.
  const nodeReach = reachRun(await loadVerve());
  if (browserRuns.reach !== nodeReach) fail("the 1-D reach's continuous actions in Chromium differ from Node.js's");
  else console.log(`page: ${nodeReach.length / 8} continuous actions of a 1-D reach in Chromium, the same bits as Node.js`);
  const references = [['Node.js', fixedRuns(await loadVerve())]];
  if (process.env.VERVE_NATIVE_PROGRAM) {
    references.push(['the native library', execFileSync(process.env.VERVE_NATIVE_PROGRAM, { encoding: 'utf8' }).trim().split('\n')]);
  }
  let same = true;
  for (const [name, lines] of references) {
    lines.forEach((line, i) => {
      if (browserRuns.lines[i] !== line) {
        fail(`fixed-seed run ${i + 1}: Chromium's actions differ from ${name}'s`);
        same = false;
      }
    });
  }
  if (same) {
    const count = browserRuns.lines.join('').length;
    console.log(`page: ${count} fixed-seed actions in Chromium, the same as ${references.map(([name]) => name).join(' and ')}`);
  }
  // Real time for the picture: the pole as a player sees it.
  await page.click('#realtime');
  await page.waitForTimeout(1500);
  await page.screenshot({ path: screenshot });
  console.log(`screenshot: ${screenshot}`);
} catch (e) {
  fail(e.message);
} finally {
  await browser.close();
  server.close();
}
process.exit(failed ? 1 : 0);
