// What the WebAssembly core's tests (core.test.cjs) and the explorer's browser test
// (explorer/tests/) share: the native CLI they compare with, a seeded generator of physical
// settings, and the 1e-12 relative comparison.
//   SELFALIGN_CLI: the native binary; default build/release's.
const assert = require('node:assert');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const { spawnSync } = require('node:child_process');

const root = path.resolve(__dirname, '..', '..');
const cli = process.env.SELFALIGN_CLI || path.join(root, 'build/release/apps/selfalign/selfalign');

// A small seeded generator (mulberry32): the same settings on every run.
function rng(seed) {
  return () => {
    seed |= 0; seed = (seed + 0x6D2B79F5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

// n physical three-phase settings on the two-region table, half with mu_static > mu (seed 26).
function settings(n, seed = 26) {
  const r = rng(seed);
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

// Runs `selfalign <args...> --config <config as a JSON file>` (no --config when config is
// null); `withDir(dir)` may add paths in
// the run's temporary folder and `after(dir)` read what the run wrote there before it is
// removed. Returns {status, stdout, stderr, after: what after returned}.
function runCli(args, config, withDir = () => [], after = () => undefined) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'selfalign-cli-'));
  try {
    const file = path.join(dir, 'c.json');
    if (config !== null) fs.writeFileSync(file, JSON.stringify(config));
    const withConfig = config === null ? [] : ['--config', file];
    const r = spawnSync(cli, [...args, ...withConfig, ...withDir(dir)], { encoding: 'utf8' });
    return { status: r.status, stdout: r.stdout, stderr: r.stderr, after: r.status === 0 ? after(dir) : undefined };
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

// The JSON a successful run prints.
function cliJson(args, config, withDir) {
  const r = runCli(args, config, withDir);
  assert.strictEqual(r.status, 0, r.stderr);
  return JSON.parse(r.stdout);
}

// `simulate --summary -`, with the trajectory written (as the page has it: stick fraction over
// the samples).
const nativeSimulate = (config) =>
  cliJson(['simulate', '--summary', '-'], config, (dir) => ['--out', path.join(dir, 't.csv')]);
const nativeSteady = (config) => cliJson(['steady', '--json'], config);
const nativeStop = (config, maxPeriods) =>
  cliJson(['stop', '--json', '--max-periods', String(maxPeriods)], config);

// A regime chart's request as `selfalign regimes` flags (keys with '_' are the flags with '-').
const regimeFlags = (request) =>
  Object.entries(request).flatMap(([k, v]) => [`--${k.replace(/_/g, '-')}`, String(v)]);

// `planar simulate --json` on a planar config given as TOML text (written to a temporary file).
function nativePlanar(text) {
  const r = runCli(['planar', 'simulate', '--json', '--quiet'], null, (dir) => {
    fs.writeFileSync(path.join(dir, 'p.toml'), text);
    return ['--config', path.join(dir, 'p.toml')];
  });
  assert.strictEqual(r.status, 0, r.stderr);
  return JSON.parse(r.stdout);
}

// The CLI's one-line message for bad input (exit 2), without its "selfalign: error: " prefix.
function cliError(args, config) {
  const r = runCli(args, config);
  assert.strictEqual(r.status, 2, `expected exit 2, got ${r.status}: ${r.stderr}`);
  const prefix = 'selfalign: error: ';
  assert.ok(r.stderr.startsWith(prefix) && r.stderr.endsWith('\n') && !r.stderr.slice(0, -1).includes('\n'),
            `one line: ${r.stderr}`);
  return r.stderr.slice(prefix.length, -1);
}

// |a - b| <= 1e-12 max(1, |b|): the "same results to 1e-12 relative" (with an absolute
// floor at 1e-12 for values near 0).
function close(a, b, what) {
  const tol = 1e-12 * Math.max(1, Math.abs(b));
  assert.ok(Math.abs(a - b) <= tol, `${what}: got ${a}, native ${b}`);
}

module.exports = { root, cli, rng, settings, runCli, nativeSimulate, nativeSteady, nativeStop,
                   regimeFlags, nativePlanar, cliError, close };
