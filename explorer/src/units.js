// Sect. 3.2's scales, for the readout of each input in the other unit system (display only: the
// core does every conversion of a run itself, from the config's `units`). L = length_scale [m],
// T = sqrt(L / (mu g)) [s], velocity L/T, acceleration mu g, jerk mu g / T (units.hpp).

export function scales(state) {
  const L = Number(state.length_scale), mu = Number(state.mu), g = Number(state.g);
  const T = Math.sqrt(L / (mu * g));
  return { length: L, time: T, velocity: L / T, acceleration: mu * g, jerk: (mu * g) / T, none: 1 };
}

export const SI_UNIT = { length: 'm', time: 's', velocity: 'm/s', acceleration: 'm/s²', jerk: 'm/s³', none: '' };

// Dimensional kinds that convert between the systems (the others are the same in both).
export function converts(dim) {
  return dim in SI_UNIT && dim !== 'none';
}

export function toSI(dim, value, sc) { return converts(dim) ? value * sc[dim] : value; }
export function fromSI(dim, value, sc) { return converts(dim) ? value / sc[dim] : value; }

// Shortest text that reads back as the same double (JavaScript's own number-to-string).
export function exact(v) {
  return v === null || v === undefined || Number.isNaN(v) ? 'none' : String(v);
}

// A short display form (4 significant digits) for readouts that are not compared.
export function short(v) {
  if (v === null || v === undefined || !Number.isFinite(v)) return 'none';
  return Number(v.toPrecision(4)).toString();
}
