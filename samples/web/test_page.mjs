// The page in headless Chromium (Debian's /usr/bin/chromium, driven by playwright-core; no browser
// is downloaded): it loads, its agent learns cart-pole in the page, and a screenshot is taken.
// `node test_page.mjs [screenshot.png]`; CHROMIUM overrides the browser's path.
// Learning is measured inside the page: the mean seconds balanced over the last 20 of 500 trials against
// trials 1-20.
import { chromium } from 'playwright-core';
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
