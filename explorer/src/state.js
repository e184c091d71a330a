// The page's state: config keys (in the state's own unit system), the map's and the stopping
// view's settings. It lives in the URL's query (a shareable link) and becomes a config for the
// core (the config files' keys, docs/config.md).
import { CONTROLS, BY_KEY, MAP_DEFAULTS, STOP_DEFAULTS } from './controls.js';
import { scales, toSI, fromSI } from './units.js';
import { FEEDER_DEFAULTS } from './feeder_view.js';

export function defaultState() {
  const s = { ...MAP_DEFAULTS, ...STOP_DEFAULTS, enabled: {}, feeder: { ...FEEDER_DEFAULTS } };
  for (const c of CONTROLS) s[c.key] = c.def;
  return s;
}

const SETTINGS = [...Object.keys(MAP_DEFAULTS), ...Object.keys(STOP_DEFAULTS)];

// Query text -> state: unknown keys are ignored, numbers parsed as written; an optional key
// present in the query is on.
export function stateFromQuery(query) {
  const s = defaultState();
  const q = new URLSearchParams(query);
  for (const [k, v] of q) {
    const c = BY_KEY[k];
    if (c) {
      s[k] = c.kind === 'number' ? Number(v) : v;
      if (c.optional) s.enabled[k] = true;
    } else if (SETTINGS.includes(k)) {
      s[k] = k === 'map_quantity' ? v : Number(v);
    } else if (k.startsWith('feeder_') && k.slice(7) in FEEDER_DEFAULTS) {
      s.feeder[k.slice(7)] = Number(v);  // the feeder view's request, "feeder_<key>"
    }
  }
  return s;
}

// State -> query text: every value that differs from its default, and every optional key on.
export function queryOfState(s) {
  const d = defaultState();
  const q = new URLSearchParams();
  for (const c of CONTROLS) {
    if (c.optional ? s.enabled[c.key] : s[c.key] !== d[c.key]) q.set(c.key, String(s[c.key]));
  }
  for (const k of SETTINGS) if (s[k] !== d[k]) q.set(k, String(s[k]));
  for (const k of Object.keys(FEEDER_DEFAULTS))
    if (s.feeder[k] !== d.feeder[k]) q.set(`feeder_${k}`, String(s.feeder[k]));
  return q.toString();
}

export function shown(c, s) {
  return !c.when || c.when(s);
}

// The config the core reads: the shown keys (optional ones only when on), in the state's units.
export function configOfState(s) {
  const config = {};
  for (const c of CONTROLS) {
    if (!shown(c, s) || (c.optional && !s.enabled[c.key]) || (c.siOnly && s.units !== 'si')) continue;
    if (c.key === 'amplitude') {
      config.fourier_cos = [s.amplitude];
      continue;
    }
    config[c.configKey ?? c.key] = c.kind === 'list' ? listOf(s[c.key]) : s[c.key];
  }
  return config;
}

// A list control's text as numbers ("" is the empty list).
export function listOf(text) {
  return String(text).trim() === '' ? [] : String(text).split(',').map((v) => Number(v));
}

// The same physical setting in the other unit system: every dimensional value converted with
// the state's scales (mu, g and L are the same in both).
export function switchUnits(s, units) {
  if (s.units === units) return s;
  const sc = scales(s);
  const out = { ...s, enabled: { ...s.enabled }, units };  // (the feeder's request is in SI and [-] alike)
  const convert = units === 'si' ? toSI : fromSI;
  for (const c of CONTROLS) {
    if (c.kind === 'number' && c.dim) out[c.key] = convert(c.dim, s[c.key], sc);
    if (c.kind === 'list') out[c.key] = listOf(s[c.key]).map((v) => convert(c.dim, v, sc)).join(',');
  }
  for (const k of ['a2_lo', 'a2_hi', 'a3_lo', 'a3_hi']) out[k] = convert('acceleration', s[k], sc);
  return out;
}
