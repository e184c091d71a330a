// The explorer in a real browser (issue 26, item 4): Playwright (playwright-core, npm) driving
// Debian's chromium headless on the page served from a loopback server (build/explorer, built by
// explorer/build.mjs). It checks that
//   - the displayed v̄, f and end position equal the native CLI's (steady --json, simulate
//     --summary) to 1e-12 relative at 20 random settings given by the page's URL (a quarter in SI);
//   - a slider move re-solves and redraws (timed by the page; reported with median and max);
//   - a 100 x 100 map is recomputed (timed; reported);
//   - a click on a map cell loads that (y2'', y3'') into the response view, equal to the CLI there;
//   - bad input shows the CLI's message next to the control, and no NaN;
// and saves screenshots and the measured times under SELFALIGN_ARTIFACTS (default
// build/explorer-artifacts).
//   node --test explorer/tests/     (CHROMIUM: the browser, default /usr/bin/chromium;
//                                    SELFALIGN_CLI: the native CLI, default build/release's)
import test from 'node:test';
import assert from 'node:assert';
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { chromium } from 'playwright-core';
import { serve } from '../serve.mjs';
import cliModule from '../../wasm/tests/cli.cjs';

const { root, settings, runCli, nativeSimulate, nativeSteady, regimeFlags, nativePlanar, cliError, close } =
  cliModule;
const artifacts = process.env.SELFALIGN_ARTIFACTS ?? join(root, 'build', 'explorer-artifacts');
mkdirSync(artifacts, { recursive: true });

let server, browser, page, base;
const measured = {};

test.before(async () => {
  server = await serve(join(root, 'build', 'explorer'));
  base = `http://127.0.0.1:${server.address().port}/`;
  browser = await chromium.launch({ executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
                                    args: ['--no-sandbox'] });
  page = await browser.newPage({ viewport: { width: 1500, height: 1400 } });
  // Offline: any request that is not to the loopback server fails the test.
  await page.route('**/*', (route) => {
    if (route.request().url().startsWith(base)) return route.continue();
    throw new Error(`the page requested ${route.request().url()}`);
  });
  page.on('pageerror', (e) => { throw e; });
});

test.after(async () => {
  writeFileSync(join(artifacts, 'timings.json'), JSON.stringify(measured, null, 2));
  await browser?.close();
  server?.close();
});

async function load(query = '') {
  await page.goto(`${base}?${query}`);
  await page.waitForSelector('body[data-ready="1"]', { timeout: 60000 });
}

const shown = (view, name) => page.textContent(`#${view} [data-number="${name}"]`);
const shownNumber = async (view, name) => {
  const text = await shown(view, name);
  assert.match(text, /^-?\d/, `${view} ${name} shows a number, not "${text}"`);
  return Number(text);
};

// Sect. 3.2's scales at the CLI's defaults (L = 1e-3 m, mu = 0.3, g = 9.81 m/s^2).
const L = 1e-3, MU_G = 0.3 * 9.81, T = Math.sqrt(L / MU_G);

// The setting as a config (the CLI's) and as the page's URL query.
function asSI(c) {
  return { ...c, units: 'si', period: c.period * T, stroke: c.stroke * L, a2: c.a2 * MU_G,
           a3: c.a3 * MU_G, x_mu: c.x_mu * L, width: c.width * L };
}
function queryOf(c) {
  const q = new URLSearchParams();
  for (const [k, v] of Object.entries(c)) if (k !== 'profile' && k !== 'friction') q.set(k, String(v));
  return q.toString();
}

// The page's run length (periods shown) is 4 where the setting does not say.
async function compareWithCli(setting, what) {
  const config = { periods: 4, ...setting };
  const steady = nativeSteady(config), run = nativeSimulate(config);
  close(await shownNumber('response', 'v_bar'), steady.v_bar, `${what}: v̄`);
  close(await shownNumber('response', 'f'), steady.f, `${what}: f`);
  close(await shownNumber('response', 'end_position'), run.final.x, `${what}: end position`);
  return Math.abs((await shownNumber('response', 'v_bar')) - steady.v_bar) / Math.max(1, Math.abs(steady.v_bar));
}

test('the displayed numbers equal the CLI at 20 random settings (URL state, a quarter in SI)', async () => {
  let worst = 0;
  const all = settings(20, 126);
  for (const [k, s] of all.entries()) {
    const config = k % 4 === 3 ? asSI(s) : s;
    await load(queryOf(config));
    worst = Math.max(worst, await compareWithCli(config, `setting ${k}`));
  }
  measured.settings_worst_relative_v_bar = worst;
  console.log(`20 settings: largest relative difference of v̄ ${worst}`);
  await page.screenshot({ path: join(artifacts, 'settings-last.png'), fullPage: true });
});

const median = (v) => { const s = [...v].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };

test('a slider move re-solves and redraws the response view (timed)', async () => {
  await load();
  const before = await page.evaluate(() => window.explorer.timings.response.length);
  const values = [];
  for (let i = 0; i < 40; ++i) values.push(Number((1.6 + 0.025 * i).toFixed(3)));
  for (const v of values) await page.fill('[data-key="a2"] .slider', String(v));
  const times = (await page.evaluate(() => window.explorer.timings.response)).slice(before);
  assert.strictEqual(times.length, values.length, 'one re-solve per slider move');
  measured.slider_ms = { median: median(times), min: Math.min(...times), max: Math.max(...times), n: times.length };
  console.log(`slider move, re-solve + redraw: median ${median(times).toFixed(2)} ms ` +
              `(min ${Math.min(...times).toFixed(2)}, max ${Math.max(...times).toFixed(2)}, n ${times.length})`);
  // the last position, against the CLI
  const a2 = values[values.length - 1];
  assert.strictEqual(await page.inputValue('[data-key="a2"] .value'), String(a2));
  await compareWithCli({ a2 }, 'after the slider');
  assert.match(page.url(), new RegExp(`a2=${a2}`), 'the state is in the URL');
  await page.screenshot({ path: join(artifacts, 'slider.png'), fullPage: true });
});

test('a 100 x 100 map is recomputed as another parameter moves (timed)', async () => {
  await load();
  const times = [];
  for (const stroke of [0.07, 0.075, 0.08, 0.09, 0.095]) {
    const before = await page.evaluate(() => window.explorer.timings.map.length);
    await page.fill('[data-key="stroke"] .value', String(stroke));
    await page.evaluate(() => window.explorer.settled());
    const t = await page.evaluate(() => window.explorer.timings.map);
    assert.strictEqual(t.length, before + 1, 'the map was recomputed');
    times.push(t[t.length - 1]);
  }
  const n = await page.evaluate(() => document.querySelector('#map .chart-map').data[0].z.flat().length);
  assert.strictEqual(n, 100 * 100);
  measured.map_100x100_ms = { median: median(times), min: Math.min(...times), max: Math.max(...times), n: times.length };
  console.log(`100 x 100 map, sweep + plotly redraw: median ${median(times).toFixed(1)} ms ` +
              `(min ${Math.min(...times).toFixed(1)}, max ${Math.max(...times).toFixed(1)}, n ${times.length})`);
});

test('a click on a map cell loads that point into the response view', async () => {
  await load();
  // the centre of cell (i2, i3) = (30, 60) in page pixels, from plotly's own axes
  const target = await page.evaluate(() => {
    const div = document.querySelector('#map .chart-map');
    const xa = div._fullLayout.xaxis, ya = div._fullLayout.yaxis, h = div.data[0];
    const box = div.querySelector('.nsewdrag').getBoundingClientRect();
    return { a2: h.x[30], a3: h.y[60], px: box.left + xa.l2p(h.x[30]), py: box.top + ya.l2p(h.y[60]) };
  });
  await page.mouse.click(target.px, target.py);
  await page.waitForFunction((t) => window.explorer.state.a2 === t.a2 && window.explorer.state.a3 === t.a3, target);
  assert.strictEqual(Number(await page.inputValue('[data-key="a2"] .value')), target.a2);
  assert.strictEqual(Number(await page.inputValue('[data-key="a3"] .value')), target.a3);
  await compareWithCli({ a2: target.a2, a3: target.a3 }, 'the clicked cell');
  await page.evaluate(() => window.explorer.settled());
  await page.screenshot({ path: join(artifacts, 'map-click.png'), fullPage: true });
});

test('bad input shows the CLI message next to the control, never NaN', async () => {
  for (const [key, value, config] of [['stroke', '5', { stroke: 5 }], ['a2', '0.9', { a2: 0.9 }]]) {
    await load();
    await page.fill(`[data-key="${key}"] .value`, value);
    const message = cliError(['simulate'], config);
    assert.strictEqual(await page.textContent(`[data-key="${key}"] .control-error`), message);
    assert.strictEqual(await page.textContent('#response .view-error'), message);
    const numbers = await page.$$eval('#response [data-number]', (els) => els.map((e) => e.textContent));
    for (const text of numbers) assert.ok(!/NaN|undefined/.test(text), `shown: ${text}`);
    // the last good plot stays, dimmed, under the message
    assert.ok(await page.evaluate(() => document.querySelector('#response').classList.contains('stale')));
    // the stopping view says the CLI's `stop` message; the map, case 0 where it holds no physical cell
    await page.evaluate(() => window.explorer.settled());
    assert.strictEqual(await page.textContent('#stop .view-error'), cliError(['stop', '--json'], config));
    if (key === 'stroke') assert.match(await page.textContent('#map .view-error'), /case 0/);
    await page.screenshot({ path: join(artifacts, `bad-${key}.png`), fullPage: true });
  }
});

test("each view exports CSV (the CLI's columns) and PNG", async () => {
  await load('periods=2');
  const saved = async (selector) => {
    const [download] = await Promise.all([page.waitForEvent('download'), page.click(selector)]);
    const file = join(artifacts, download.suggestedFilename());
    await download.saveAs(file);
    return { name: download.suggestedFilename(), file };
  };
  const { readFileSync } = await import('node:fs');
  const response = await saved('#response .export-csv');
  const lines = readFileSync(response.file, 'utf8').trim().split('\n');
  assert.strictEqual(lines[0], 't,x,x_dot,y,y_dot,y_ddot,stick');  // io/trajectory_csv.hpp's header
  // the last row is the run's end: the displayed end position
  assert.strictEqual(Number(lines[lines.length - 1].split(',')[1]), await shownNumber('response', 'end_position'));
  const map = await saved('#map .export-csv');
  const mapLines = readFileSync(map.file, 'utf8').trim().split('\n');
  assert.strictEqual(mapLines[0], 'a2,a3,case_a_priori,case,v_bar,f');
  assert.strictEqual(mapLines.length, 1 + 100 * 100);
  const stop = await saved('#stop .export-csv');
  assert.strictEqual(readFileSync(stop.file, 'utf8').split('\n')[0], 't,x,x_dot,stick');
  for (const view of ['response', 'map', 'stop']) {
    const png = await saved(`#${view} .export-png`);
    const bytes = readFileSync(png.file);
    assert.deepStrictEqual([...bytes.subarray(1, 4)], [0x50, 0x4e, 0x47], `${png.name} is a PNG`);
  }
});

test('switching to SI keeps the physical setting and shows the CLI numbers in SI', async () => {
  await load();
  const vDimensionless = await shownNumber('response', 'v_bar');
  await page.selectOption('[data-key="units"] select', 'si');
  await page.waitForFunction(() => window.explorer.state.units === 'si');
  const setting = { units: 'si' };
  for (const key of ['period', 'stroke', 'a2', 'a3', 'x_mu', 'width', 'x0', 'v0'])
    setting[key] = Number(await page.inputValue(`[data-key="${key}"] .value`));
  await compareWithCli(setting, 'in SI');
  // the same motion: v̄ [m/s] = v̄ [-] L/T (Sect. 3.2), to rounding of the conversions
  const vSI = await shownNumber('response', 'v_bar');
  assert.ok(Math.abs(vSI - vDimensionless * (L / T)) <= 1e-9 * Math.abs(vSI), `${vSI} vs ${vDimensionless * L / T}`);
  assert.match(page.url(), /units=si/);
  assert.strictEqual(await page.textContent('#response [data-unit="velocity"]'), '[m/s]');
  await page.screenshot({ path: join(artifacts, 'si.png'), fullPage: true });
});

test('the feeder regime chart shows `selfalign regimes` counts (its request in the URL)', async () => {
  const request = { mu_static: 0.6, mu_kinetic: 0.45, incline: 0.05, angles: 9, machine_numbers: 7, periods: 8 };
  await load(Object.entries(request).map(([k, v]) => `feeder_${k}=${v}`).join('&'));
  const flags = regimeFlags(request);
  const r = runCli(['regimes', ...flags, '--json', '--quiet'], null);
  assert.strictEqual(r.status, 0, r.stderr);
  const { regimes } = JSON.parse(r.stdout);
  const shownCounts = Object.fromEntries((await shown('feeder', 'regimes')).split(', ').map((p) => {
    const [name, count] = p.split(' ');
    return [name, Number(count)];
  }));
  assert.deepStrictEqual(shownCounts, regimes);
  // an input of the view re-solves it and enters the URL; bad input shows the CLI's message
  await page.fill('[data-feeder="mu_kinetic"]', '0.7');
  await page.dispatchEvent('[data-feeder="mu_kinetic"]', 'change');
  assert.strictEqual(await page.textContent('#feeder .view-error'),
                     cliError(['regimes', ...flags.slice(0, 2), '--mu-kinetic', '0.7', '--quiet'], null));
  assert.match(page.url(), /feeder_mu_kinetic=0\.7/);
});

test('the planar view runs its config as `selfalign planar simulate` does', async () => {
  await load();
  await page.evaluate(() => window.explorer.planarDone());
  const text = await page.inputValue('#planar .planar-config');
  const native = nativePlanar(text);
  close(await shownNumber('planar', 'end_x'), native.end_pose.x, 'planar end x');
  close(await shownNumber('planar', 'end_y'), native.end_pose.y, 'planar end y');
  assert.strictEqual(await shown('planar', 'census'),
                     `stick ${native.census.stick}, pivot ${native.census.pivot}, slip ${native.census.slip}`);
  // a bad key: the message names it with its section
  await page.fill('#planar .planar-config', text.replace(/^step = 4e-5/m, 'step = -1'));
  await page.click('#planar .planar-run');
  await page.evaluate(() => window.explorer.planarDone());
  assert.match(await page.textContent('#planar .view-error'), /run\.step/);
  await page.screenshot({ path: join(artifacts, 'feeder-planar.png'), fullPage: true });
});

test('the quadratic-sequence and piecewise-linear families (list inputs) equal the CLI', async () => {
  await load('profile=quadratic-sequence');
  await compareWithCli({ profile: 'quadratic-sequence', durations: [0.3, 0.2, 0.5], accelerations: [2, -6, 1.2] },
                       'quadratic sequence (the page defaults)');
  await load('profile=piecewise-linear&times=0,0.2,0.5&pl_accelerations=3,-5.8,1');
  const piecewise = { profile: 'piecewise-linear', times: [0, 0.2, 0.5], accelerations: [3, -5.8, 1] };
  await compareWithCli(piecewise, 'piecewise-linear');
  // accelerations that do not integrate to 0: the CLI's message under that list
  await page.fill('[data-key="pl_accelerations"] .value', '3,-4,1');
  assert.strictEqual(await page.textContent('[data-key="pl_accelerations"] .control-error'),
                     cliError(['simulate'], { ...piecewise, accelerations: [3, -4, 1] }));
  assert.match(page.url(), /pl_accelerations=3%2C-4%2C1/);
});
