// The explorer page (issue 26; docs/explorer.md): every change re-solves with the C++ core in
// WebAssembly. The response view re-solves at once; the map and the stopping view follow when
// the input rests (kSettleMs), the map only when something other than (y2'', y3'') changed.
import 'uplot/dist/uPlot.min.css';
import './style.css';
import { loadCore, CoreError } from './core.js';
import { stateFromQuery, queryOfState, configOfState } from './state.js';
import { ControlPanel } from './control_panel.js';
import { ResponseView } from './response_view.js';
import { MapView } from './map_view.js';
import { StopView } from './stop_view.js';
import { FeederView } from './feeder_view.js';
import { PlanarView } from './planar_view.js';
import { SI_UNIT } from './units.js';

const kSettleMs = 150;

const microtask = () => new Promise((r) => queueMicrotask(r));

async function start() {
  const core = await loadCore();
  const state = stateFromQuery(location.search);
  const timings = { response: [], map: [], stop: [], feeder: [], planar: [] };
  const unitLabel = (dim) => (state.units === 'si' && SI_UNIT[dim] ? `[${SI_UNIT[dim]}]` : '[-]');
  let lastKey = null;

  const response = new ResponseView(document.getElementById('response'));
  const map = new MapView(document.getElementById('map'), (a2, a3) => {
    state.a2 = a2;
    state.a3 = a3;
    panel.refresh();
    changed('a2');
  });
  const stop = new StopView(document.getElementById('stop'));
  const feeder = new FeederView(document.getElementById('feeder'), state.feeder);
  const planar = new PlanarView(document.getElementById('planar'), () => solvePlanar());
  const panel = new ControlPanel(document.getElementById('controls'), state, (key) => changed(key));

  // The core's message in the view; next to the controls only for the response view's run
  // (the map and the stopping run read the same config, so they fail for the same keys).
  function report(view, error, blame) {
    if (!(error instanceof CoreError)) throw error;
    if (view === response) panel.showError(error.message, error.keys, blame);
    view.fail(error.message);
  }

  // The response view: simulate + steady state, drawn; timed to the end of uPlot's redraw.
  async function solveResponse() {
    const t0 = performance.now();
    const config = configOfState(state);
    try {
      const run = core.simulate(config);
      const steady = core.steady(config);
      panel.clearErrors();
      response.clearError();
      response.show(run, steady, unitLabel);
    } catch (e) {
      report(response, e, lastKey);
    }
    await microtask();  // uPlot draws in a microtask queued by setData
    timings.response.push(performance.now() - t0);
  }

  let mapKey = null;
  async function solveMap() {
    const config = configOfState(state);
    if (config.profile !== 'three-phase') {
      map.fail("the (y2'', y3'') map needs profile = three-phase");
      return;
    }
    const { a2, a3, x0, v0, periods, ...rest } = config;
    const key = JSON.stringify([rest, state.map_n, state.map_quantity, state.a2_lo, state.a2_hi, state.a3_lo, state.a3_hi]);
    if (key === mapKey) { map.mark(state.a2, state.a3); return; }
    const t0 = performance.now();
    try {
      const n = Math.round(state.map_n);
      const cells = core.sweep(config, state.a2_lo, state.a2_hi, n, state.a3_lo, state.a3_hi, n);
      map.clearError();
      await map.show(cells, state.map_quantity, state.a2, state.a3, unitLabel);
      mapKey = key;
      timings.map.push(performance.now() - t0);
    } catch (e) {
      mapKey = null;
      report(map, e, null);
    }
  }

  async function solveStop() {
    const t0 = performance.now();
    try {
      const r = core.stop(configOfState(state), Math.round(state.max_periods));
      stop.clearError();
      await stop.show(r, unitLabel);
      timings.stop.push(performance.now() - t0);
    } catch (e) {
      report(stop, e, null);
    }
  }

  // The feeder's regime chart and the planar run have their own inputs (the page's other
  // controls do not enter them): solved on their own changes.
  async function solveFeeder() {
    try {
      feeder.clearError();
      timings.feeder.push(await feeder.solve(core));
    } catch (e) {
      report(feeder, e, null);
    }
  }
  feeder.onChange = () => {
    history.replaceState(null, '', `?${queryOfState(state)}`);
    return solveFeeder();
  };

  let planarDone = Promise.resolve();
  function solvePlanar() {
    planarDone = (async () => {
      try {
        planar.clearError();
        timings.planar.push(await planar.solve(core));
      } catch (e) {
        report(planar, e, null);
      }
    })();
    return planarDone;
  }

  let settle = null;
  let settled = Promise.resolve();
  function changed(key) {
    lastKey = key;
    history.replaceState(null, '', `?${queryOfState(state)}`);
    const done = solveResponse();
    clearTimeout(settle);
    settled = new Promise((resolve) => {
      settle = setTimeout(async () => { await solveMap(); await solveStop(); resolve(); }, kSettleMs);
    });
    return done;
  }

  // The map's own settings.
  for (const id of ['map_n', 'map_quantity', 'a2_lo', 'a2_hi', 'a3_lo', 'a3_hi', 'max_periods']) {
    const el = document.getElementById(id);
    el.value = String(state[id]);
    el.addEventListener('change', () => {
      state[id] = el.tagName === 'SELECT' ? el.value : Number(el.value);
      changed(id);
    });
  }

  await solveResponse();
  await solveMap();
  await solveStop();
  await solveFeeder();
  await solvePlanar();
  // For the browser test and the curious: the state, the core and the measured times [ms].
  window.explorer = { state, core, timings, settled: () => settled, planarDone: () => planarDone };
  document.body.dataset.ready = '1';
}

start().catch((e) => {
  document.getElementById('fatal').textContent = `the explorer could not start: ${e.message}`;
  throw e;
});
