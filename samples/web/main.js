// The page: a cart-pole agent learning live (cart_pole.js), drawn on three canvases: the scene,
// the value map V(angle, angular velocity) sampled from the agent, and the learning curve.
// ?speed=fast|realtime picks the start mode; window.verveDemo exposes the numbers (the headless
// test in test_page.mjs reads them).
import { loadVerve } from '../../bindings/web/src/index.js';
import { CartPole, CART_POLE_AGENT, AGENT_DT } from './cart_pole.js';

const params = new URLSearchParams(location.search);
const $ = (id) => document.getElementById(id);
const demo = (window.verveDemo = { ready: false, error: null, trials: 0, history: [], best: 0, rbfs: 0, stepsPerSecond: 0 });

let verve;
let agent;
let cartPole;
let fast = params.get('speed') !== 'realtime';
let seed = Number(params.get('seed') ?? 1);

function newAgent() {
  agent?.dispose();
  agent = verve.createAgent({ ...CART_POLE_AGENT, seed: seed++ });
  cartPole = new CartPole(agent);
}

function setFast(on) {
  fast = on;
  $('fast').setAttribute('aria-pressed', String(on));
  $('realtime').setAttribute('aria-pressed', String(!on));
}

function drawScene(ctx) {
  const { width: w, height: h } = ctx.canvas;
  ctx.clearRect(0, 0, w, h);
  const scale = (w - 40) / 4.8;          // pixels per metre
  const ground = h - 40;
  ctx.strokeStyle = '#556';
  ctx.lineWidth = 2;
  ctx.beginPath();
  ctx.moveTo(20, ground);
  ctx.lineTo(w - 20, ground);
  ctx.stroke();
  const cx = w / 2 + cartPole.x * scale;
  ctx.fillStyle = '#3d6fd6';
  ctx.fillRect(cx - 30, ground - 24, 60, 24);
  const length = 1.0 * scale * 1.4;      // the 1 m pole, drawn a little longer to be seen
  ctx.strokeStyle = '#f2b33d';
  ctx.lineWidth = 6;
  ctx.beginPath();
  ctx.moveTo(cx, ground - 24);
  ctx.lineTo(cx + Math.sin(cartPole.theta) * length, ground - 24 - Math.cos(cartPole.theta) * length);
  ctx.stroke();
  const arrow = [-1, 1, 0][cartPole.action];
  if (arrow) {
    ctx.fillStyle = '#e6e6e6';
    ctx.beginPath();
    const ax = cx + arrow * 42;
    ctx.moveTo(ax + arrow * 10, ground - 12);
    ctx.lineTo(ax, ground - 20);
    ctx.lineTo(ax, ground - 4);
    ctx.fill();
  }
}

const N = 48;  // value map samples per axis
const valueImage = document.createElement('canvas');  // N x N, scaled up onto the visible canvas
valueImage.width = N;
valueImage.height = N;
function drawValues(ctx) {
  const v = agent.sampleValues(
    [{ kind: 'continuous', index: 2, samples: N }, { kind: 'continuous', index: 3, samples: N }],
    { continuous: [0, 0, 0, 0] },
  );
  let lo = Infinity;
  let hi = -Infinity;
  for (const x of v) {
    lo = Math.min(lo, x);
    hi = Math.max(hi, x);
  }
  const image = ctx.createImageData(N, N);
  for (let j = 0; j < N; ++j) {
    for (let i = 0; i < N; ++i) {
      const t = hi > lo ? ((v[j * N + i] - lo) / (hi - lo)) ** 3 : 0.5;  // cubed: the top shows its shape
      const p = ((N - 1 - j) * N + i) * 4;  // angular velocity upwards
      image.data[p] = Math.round(255 * Math.min(1, 2 * t));
      image.data[p + 1] = Math.round(255 * t * t);
      image.data[p + 2] = Math.round(255 * (1 - t) * 0.6);
      image.data[p + 3] = 255;
    }
  }
  valueImage.getContext('2d').putImageData(image, 0, 0);
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(valueImage, 0, 0, ctx.canvas.width, ctx.canvas.height);
  // The pole's current state, as a dot.
  const px = ((cartPole.theta / ((12 * Math.PI) / 180) + 1) / 2) * ctx.canvas.width;
  const py = (1 - (cartPole.omega / ((100 * Math.PI) / 180) + 1) / 2) * ctx.canvas.height;
  ctx.fillStyle = '#fff';
  ctx.beginPath();
  ctx.arc(px, py, 3, 0, 2 * Math.PI);
  ctx.fill();
}

function drawCurve(ctx) {
  const { width: w, height: h } = ctx.canvas;
  ctx.clearRect(0, 0, w, h);
  const history = cartPole.history;
  const lo = Math.log10(0.1);
  const hi = Math.log10(1800);
  const y = (s) => h - 20 - ((Math.log10(Math.max(s, 0.1)) - lo) / (hi - lo)) * (h - 30);
  ctx.strokeStyle = '#334';
  ctx.fillStyle = '#778';
  ctx.font = '11px sans-serif';
  ctx.lineWidth = 1;
  for (const s of [0.1, 1, 10, 100, 1800]) {
    ctx.beginPath();
    ctx.moveTo(30, y(s));
    ctx.lineTo(w, y(s));
    ctx.stroke();
    ctx.fillText(String(s), 2, y(s) + 4);
  }
  const n = Math.max(history.length, 10);
  const x = (i) => 30 + (i / n) * (w - 35);
  ctx.fillStyle = '#5a6a8a';
  history.forEach((s, i) => ctx.fillRect(x(i), y(s), 1.5, 1.5));
  // A running mean over 20 trials.
  ctx.strokeStyle = '#f2b33d';
  ctx.lineWidth = 2;
  ctx.beginPath();
  let sum = 0;
  history.forEach((s, i) => {
    sum += s;
    if (i >= 20) sum -= history[i - 20];
    const mean = sum / Math.min(i + 1, 20);
    if (i === 0) ctx.moveTo(x(i), y(mean));
    else ctx.lineTo(x(i), y(mean));
  });
  ctx.stroke();
  ctx.fillStyle = '#99a';
  ctx.fillText(`trial ${history.length}`, w - 70, h - 4);
}

let simulated = 0;     // seconds of simulated time owed to real time
let last = performance.now();
let lastValues = 0;
let stepsThisSecond = 0;
let secondStart = last;

function frame(now) {
  try {
    if (fast) {
      const until = performance.now() + 12;  // ~12 ms of learning per frame
      while (performance.now() < until) {
        for (let k = 0; k < 50; ++k) cartPole.step();
        stepsThisSecond += 50;
      }
    } else {
      simulated += Math.min(now - last, 100) / 1000;
      while (simulated >= AGENT_DT) {
        cartPole.step();
        ++stepsThisSecond;
        simulated -= AGENT_DT;
      }
    }
    last = now;
    if (now - secondStart >= 1000) {
      demo.stepsPerSecond = Math.round((stepsThisSecond * 1000) / (now - secondStart));
      stepsThisSecond = 0;
      secondStart = now;
    }
    const history = cartPole.history;
    demo.trials = history.length;
    demo.history = history;
    demo.best = Math.max(demo.best, cartPole.seconds, history.at(-1) ?? 0);
    demo.rbfs = agent.rbfCount();
    drawScene($('scene').getContext('2d'));
    if (now - lastValues > 250) {
      drawValues($('values').getContext('2d'));
      drawCurve($('curve').getContext('2d'));
      lastValues = now;
    }
    $('status').textContent =
      `trial ${history.length + 1}   balanced ${cartPole.seconds.toFixed(1)} s   best ${demo.best.toFixed(1)} s   ` +
      `RBFs ${demo.rbfs}   ${demo.stepsPerSecond} agent steps/s (${fast ? 'fast' : 'real time'})`;
    requestAnimationFrame(frame);
  } catch (e) {
    demo.error = String(e?.stack ?? e);
    $('status').textContent = `error: ${e.message}`;
    throw e;
  }
}

try {
  verve = await loadVerve();
  newAgent();
  setFast(fast);
  $('fast').onclick = () => setFast(true);
  $('realtime').onclick = () => setFast(false);
  $('reset').onclick = () => {
    newAgent();
    demo.best = 0;
  };
  demo.ready = true;
  demo.version = verve.version().text;
  requestAnimationFrame(frame);
} catch (e) {
  demo.error = String(e?.stack ?? e);
  $('status').textContent = `could not start: ${e.message}`;
}
