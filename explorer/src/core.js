// The C++ core in WebAssembly (wasm/api.cpp), loaded from the page's own folder: configs in and
// results out as JSON; the core's {"error": ...} becomes a CoreError carrying the CLI's line.

export class CoreError extends Error {
  // The config keys the message names ("invalid a2, a3 = ...": ['a2', 'a3']).
  get keys() {
    const m = /^invalid ([^=]+?) = /.exec(this.message);
    return m ? m[1].split(',').map((k) => k.trim().replace(/-/g, '_')) : [];
  }
}

function parsed(text) {
  const j = JSON.parse(text);
  if (j && typeof j === 'object' && !Array.isArray(j) && 'error' in j) throw new CoreError(j.error);
  return j;
}

export async function loadCore() {
  // selfalign_core.js (a UMD factory) is loaded by a <script> tag before the bundle.
  const module = await globalThis.createSelfalign();
  return {
    simulate: (config) => parsed(module.simulate(JSON.stringify(config))),
    steady: (config) => parsed(module.steady(JSON.stringify(config))),
    sweep: (config, a2lo, a2hi, n2, a3lo, a3hi, n3) =>
      parsed(module.sweep(JSON.stringify(config), a2lo, a2hi, n2, a3lo, a3hi, n3)),
    stop: (config, maxPeriods) => parsed(module.stop(JSON.stringify(config), maxPeriods)),
    regimes: (request) => parsed(module.regimes(JSON.stringify(request))),
    planar: (text, format) => parsed(module.planar(text, format)),
  };
}
