// The WebAssembly core (wasm/api.cpp, issue 26) against the native CLI: 20 random settings of
// a run (three-phase profile, accelerations, stroke, period, law, two-region friction), each
// simulated by the wasm module and by `selfalign simulate --config C --summary -`; the end
// position, end velocity, v̄ over the last period and the stick fraction agree to 1e-12
// relative (floor 1e-12 absolute). Bad input gives the CLI's message.
//   node --test wasm/tests/   (SELFALIGN_CLI: the native binary; default build/release's)
const test = require('node:test');
const assert = require('node:assert');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const { execFileSync, spawnSync } = require('node:child_process');

const root = path.resolve(__dirname, '..', '..');
const cli = process.env.SELFALIGN_CLI || path.join(root, 'build/release/apps/selfalign/selfalign');
const wasmDir = path.join(root, 'build/wasm');

let core;
test.before(async () => {
  const create = require(path.join(wasmDir, 'selfalign_core.js'));
  core = await create({ wasmBinary: fs.readFileSync(path.join(wasmDir, 'selfalign_core.wasm')) });
});

// A small seeded generator (mulberry32): the same 20 settings on every run.
function rng(seed) {
  return () => {
    seed |= 0; seed = (seed + 0x6D2B79F5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function settings(n) {
  const r = rng(26);
  const out = [];
  while (out.length < n) {
    const period = 0.5 + r();
    const stroke = 0.05 + 0.05 * r();
    const a2 = 1.2 + 2 * r(), a3 = 1.1 + 2 * r();
    // physical (eq. 28): 1/a2 + 1/a3 <= period^2 / (8 stroke)
    if (1 / a2 + 1 / a3 > period * period / (8 * stroke)) continue;
    const c = { profile: 'three-phase', period, stroke, a2, a3, periods: 5 + Math.floor(10 * r()),
                friction: 'two-region', x_mu: 0.1 + 0.3 * r(), width: 0.02 + 0.05 * r(),
                c_mu: 2 + 2 * r() };
    c.mu = 0.3;
    if (r() < 0.5) c.mu_static = 0.3 * (1 + 0.3 * r());
    out.push(c);
  }
  return out;
}

function native(config) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'selfalign-wasm-'));
  try {
    const file = path.join(dir, 'c.json');
    fs.writeFileSync(file, JSON.stringify(config));
    // with the trajectory written, as the page records it (stick fraction over the samples)
    return JSON.parse(execFileSync(cli, ['simulate', '--config', file, '--out',
                                         path.join(dir, 't.csv'), '--summary', '-']));
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

function close(a, b, what) {
  const tol = 1e-12 * Math.max(1, Math.abs(b));
  assert.ok(Math.abs(a - b) <= tol, `${what}: wasm ${a} vs native ${b}`);
}

test('simulate agrees with the native CLI at 20 random settings', () => {
  let worst = 0;
  for (const c of settings(20)) {
    const w = JSON.parse(core.simulate(JSON.stringify(c)));
    assert.ok(!w.error, w.error);
    const n = native(c);
    close(w.final.x, n.final.x, 'final x');
    close(w.final.x_dot, n.final.x_dot, 'final x_dot');
    close(w.mean_velocity_last_period, n.mean_velocity_last_period, 'v_bar last period');
    close(w.stick_fraction, n.stick_fraction, 'stick fraction');
    assert.strictEqual(w.arcs, n.arcs);
    worst = Math.max(worst, Math.abs(w.final.x - n.final.x) / Math.max(1, Math.abs(n.final.x)));
  }
  console.log(`largest relative difference of the end position: ${worst}`);
});

test('bad input gives the CLI message', () => {
  const bad = { profile: 'three-phase', a2: 0.5, a3: 0.5 };
  const w = JSON.parse(core.simulate(JSON.stringify(bad)));
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'selfalign-wasm-'));
  const file = path.join(dir, 'c.json');
  fs.writeFileSync(file, JSON.stringify(bad));
  const n = spawnSync(cli, ['simulate', '--config', file], { encoding: 'utf8' });
  fs.rmSync(dir, { recursive: true, force: true });
  assert.strictEqual(n.status, 2);
  assert.strictEqual(`selfalign: error: ${w.error}\n`, n.stderr);
  const unknown = JSON.parse(core.simulate(JSON.stringify({ stroke: -1 })));
  assert.match(unknown.error, /stroke/);
});
