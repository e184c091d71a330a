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

function nativeSteady(config) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'selfalign-wasm-'));
  try {
    const file = path.join(dir, 'c.json');
    fs.writeFileSync(file, JSON.stringify(config));
    return JSON.parse(execFileSync(cli, ['steady', '--config', file, '--json']));
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

test('steady state agrees with the native CLI at 20 random settings', () => {
  let worst = 0;
  for (const s of settings(20)) {
    // the uniform table's keys only (steady takes no friction map, initial state or run length)
    const c = { profile: s.profile, period: s.period, stroke: s.stroke, a2: s.a2, a3: s.a3,
                mu: s.mu };
    if (s.mu_static !== undefined) c.mu_static = s.mu_static;
    const w = JSON.parse(core.steady(JSON.stringify(c)));
    assert.ok(!w.error, w.error);
    const n = nativeSteady(c);
    assert.strictEqual(w.case, n.case);
    assert.strictEqual(w.pattern, n.pattern);
    close(w.v_bar, n.v_bar, 'v_bar');
    close(w.f, n.f, 'f');
    close(w.x_dot_0s, n.x_dot_0s, "x'_0s");
    worst = Math.max(worst, Math.abs(w.v_bar - n.v_bar) / Math.max(1, Math.abs(n.v_bar)));
  }
  console.log(`largest relative difference of v_bar: ${worst}`);
  // a non-physical request is a result, case 0, as in the CLI
  const zero = { profile: 'three-phase', a2: 0.5, a3: 0.5 };
  const w0 = JSON.parse(core.steady(JSON.stringify(zero)));
  assert.strictEqual(w0.case, 0);
  assert.strictEqual(w0.case, nativeSteady(zero).case);
});

// `sweep accelerations --out cells.csv`: a2,a3,case_a_priori,case,v_bar,f,x_dot_0s,converged,status
function nativeSweep(config, r2, r3) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'selfalign-wasm-'));
  try {
    const file = path.join(dir, 'c.json'), out = path.join(dir, 'cells.csv');
    fs.writeFileSync(file, JSON.stringify(config));
    execFileSync(cli, ['sweep', 'accelerations', '--config', file, '--a2-range', r2.join(':'),
                       '--a3-range', r3.join(':'), '--out', out, '--quiet']);
    const [header, ...rows] = fs.readFileSync(out, 'utf8').trim().split('\n');
    const cols = header.split(',');
    return rows.map(r => Object.fromEntries(r.split(',').map((v, i) => [cols[i], v])));
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

test('the (a2, a3) sweep agrees with the native CLI cell by cell', () => {
  const config = { profile: 'three-phase', period: 1, stroke: 0.084, mu: 0.3 };
  const r2 = [1.2, 4, 8], r3 = [1.1, 3, 6];
  const w = JSON.parse(core.sweep(JSON.stringify(config), r2[0], r2[1], r2[2], r3[0], r3[1], r3[2]));
  assert.ok(!w.error, w.error);
  const n = nativeSweep(config, r2, r3);
  assert.strictEqual(n.length, w.v_bar.length);
  n.forEach((row, k) => {
    assert.strictEqual(w.case[k], Number(row.case), `case of cell ${k}`);
    assert.strictEqual(w.case_a_priori[k], Number(row.case_a_priori));
    for (const key of ['v_bar', 'f']) {
      const native = row[key] === 'nan' || row[key] === '' ? null : Number(row[key]);
      if (native === null || w[key][k] === null) assert.strictEqual(w[key][k], native, key);
      else close(w[key][k], native, `${key} of cell ${k}`);
    }
  });
  // The interaction budget of the page: a 100 x 100 map, timed (reported, not asserted here).
  const t0 = process.hrtime.bigint();
  const big = JSON.parse(core.sweep(JSON.stringify(config), 1.2, 6, 100, 1.1, 6, 100));
  const ms = Number(process.hrtime.bigint() - t0) / 1e6;
  assert.strictEqual(big.v_bar.length, 10000);
  console.log(`100 x 100 map in the wasm core: ${ms.toFixed(1)} ms`);
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
