// The WebAssembly core (wasm/api.cpp, issue 26) against the native CLI: 20 random settings of
// a run (three-phase profile, accelerations, stroke, period, law, two-region friction), each
// simulated by the wasm module and by `selfalign simulate --config C --summary -`; the end
// position, end velocity, v̄ over the last period and the stick fraction agree to 1e-12
// relative (floor 1e-12 absolute). Bad input gives the CLI's message.
//   node --test wasm/tests/   (SELFALIGN_CLI: the native binary; default build/release's)
const test = require('node:test');
const assert = require('node:assert');
const fs = require('node:fs');
const path = require('node:path');

const { root, settings, runCli, nativeSimulate, nativeSteady, nativeStop, regimeFlags, nativePlanar,
        cliError, close } = require('./cli.cjs');
const wasmDir = path.join(root, 'build/wasm');

let core;
test.before(async () => {
  const create = require(path.join(wasmDir, 'selfalign_core.js'));
  core = await create({ wasmBinary: fs.readFileSync(path.join(wasmDir, 'selfalign_core.wasm')) });
});

test('simulate agrees with the native CLI at 20 random settings', () => {
  let worst = 0;
  for (const c of settings(20)) {
    const w = JSON.parse(core.simulate(JSON.stringify(c)));
    assert.ok(!w.error, w.error);
    const n = nativeSimulate(c);
    close(w.final.x, n.final.x, 'final x');
    close(w.final.x_dot, n.final.x_dot, 'final x_dot');
    close(w.mean_velocity_last_period, n.mean_velocity_last_period, 'v_bar last period');
    close(w.stick_fraction, n.stick_fraction, 'stick fraction');
    assert.strictEqual(w.arcs, n.arcs);
    worst = Math.max(worst, Math.abs(w.final.x - n.final.x) / Math.max(1, Math.abs(n.final.x)));
  }
  console.log(`largest relative difference of the end position: ${worst}`);
});

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
  const r = runCli(['sweep', 'accelerations', '--a2-range', r2.join(':'), '--a3-range', r3.join(':'),
                    '--quiet'], config, (dir) => ['--out', path.join(dir, 'cells.csv')],
                   (dir) => fs.readFileSync(path.join(dir, 'cells.csv'), 'utf8'));
  assert.strictEqual(r.status, 0, r.stderr);
  const [header, ...rows] = r.after.trim().split('\n');
  const cols = header.split(',');
  return rows.map(row => Object.fromEntries(row.split(',').map((v, i) => [cols[i], v])));
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
  assert.strictEqual(w.error, cliError(['simulate'], bad));
  const unknown = JSON.parse(core.simulate(JSON.stringify({ stroke: -1 })));
  assert.match(unknown.error, /stroke/);
  // stop on a table without a rise of friction: the CLI's refusal, word for word
  const uniform = { friction: 'uniform' };
  assert.strictEqual(JSON.parse(core.stop(JSON.stringify(uniform), 100)).error,
                     cliError(['stop', '--json'], uniform));
});

test('stopping runs agree with the native CLI at 20 random settings', () => {
  let worst = 0;
  for (const s of settings(20, 59)) {
    const c = { ...s, x0: s.x_mu - 0.2 };
    delete c.periods;
    const w = JSON.parse(core.stop(JSON.stringify(c), 3000));
    assert.ok(!w.error, w.error);
    const n = nativeStop(c, 3000);
    assert.strictEqual(w.stop, n.stop);
    assert.strictEqual(w.accumulation_proven, n.accumulation_proven);
    assert.strictEqual(w.stick_positions.length, n.stick_positions.length);
    for (const key of ['end_position', 'x_stick_min', 'entry_time', 'process_time']) {
      if (n[key] === null) assert.strictEqual(w[key], null, key);
      else close(w[key], n[key], key);
    }
    w.stick_positions.forEach((x, k) => close(x, n.stick_positions[k], `stick position ${k}`));
    if (n.end_position !== null)
      worst = Math.max(worst, Math.abs(w.end_position - n.end_position) / Math.max(1, Math.abs(n.end_position)));
    // the trajectory ends where the CLI's --out does, and the map's fixed point is x_stick,min
    // where eq. (59) applies (the paper's law: mu_static = mu)
    assert.ok(w.trajectory.t.length > 1);
    if (w.map && c.mu_static === undefined && n.stop === 'accumulation') close(w.map.fixed_point, n.x_stick_min, 'fixed point');
  }
  console.log(`largest relative difference of the stopping end position: ${worst}`);
});

test('the feeder regime chart agrees with `selfalign regimes` cell by cell', () => {
  const request = { mu_static: 0.5, mu_kinetic: 0.4, incline: 0.05, angles: 7, machine_numbers: 6,
                    angle_min: 0.1, angle_max: 1.1, k_min: 0.2, k_max: 5, periods: 8 };
  const w = JSON.parse(core.regimes(JSON.stringify(request)));
  assert.ok(!w.error, w.error);
  const r = runCli(['regimes', ...regimeFlags(request), '--json', '--quiet'], null,
                   (dir) => ['--csv', path.join(dir, 'cells.csv')],
                   (dir) => fs.readFileSync(path.join(dir, 'cells.csv'), 'utf8'));
  assert.strictEqual(r.status, 0, r.stderr);
  const summary = JSON.parse(r.stdout);
  assert.deepStrictEqual(w.regimes, summary.regimes);
  assert.strictEqual(w.failed, summary.failed);
  const [header, ...rows] = r.after.trim().split('\n');
  const cols = header.split(',');
  assert.strictEqual(rows.length, w.rows.regime.length);
  rows.forEach((line, k) => {
    const row = Object.fromEntries(line.split(',').map((v, i) => [cols[i], v]));
    for (const key of ['regime', 'first_event', 'status']) assert.strictEqual(w.rows[key][k], row[key], `${key} of cell ${k}`);
    assert.strictEqual(String(w.rows.lifted_off[k]), row.lifted_off);
    for (const key of ['vibration_angle_rad', 'machine_number', 'throw_number', 'dimensionless_speed',
                       'stick_fraction', 'flight_fraction']) {
      const native = row[key] === 'nan' || row[key] === '' ? null : Number(row[key]);
      if (native === null || w.rows[key][k] === null) assert.strictEqual(w.rows[key][k], native, key);
      else close(w.rows[key][k], native, `${key} of cell ${k}`);
    }
  });
  // bad input: the CLI's flag name in the message
  assert.strictEqual(JSON.parse(core.regimes(JSON.stringify({ mu_static: 0.5, mu_kinetic: 0.6 }))).error,
                     cliError(['regimes', '--mu-static', '0.5', '--mu-kinetic', '0.6', '--quiet'], null));
});

test('a planar run agrees with `selfalign planar simulate` (examples/planar.toml, 20 periods)', () => {
  const text = fs.readFileSync(path.join(root, 'examples/planar.toml'), 'utf8')
    .replace(/^periods = 200\b/m, 'periods = 20');
  assert.ok(text.includes('periods = 20\n') || /^periods = 20\b/m.test(text));
  const w = JSON.parse(core.planar(text, 'toml'));
  assert.ok(!w.error, w.error);
  const n = nativePlanar(text);
  for (const key of ['x', 'y', 'angle_rad']) close(w.end_pose[key], n.end_pose[key], `end pose ${key}`);
  for (const key of ['ux', 'uy', 'omega']) close(w.end_twist[key], n.end_twist[key], `end twist ${key}`);
  assert.deepStrictEqual(w.census, n.census);
  assert.strictEqual(w.trajectory.t.length, w.trajectory.mode.length);
  // a config error names the key with its section, as the CLI's
  assert.match(JSON.parse(core.planar(text.replace(/^step = 4e-5/m, 'step = -1'), 'toml')).error, /run\.step/);
});
