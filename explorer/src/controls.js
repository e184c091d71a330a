// The explorer's inputs: one entry per config key (docs/config.md), with its dimension (for the
// SI <-> dimensionless readout), the range of its slider in dimensionless units [-] and its
// default (the paper's Sect. 7.2 setting, as the CLI's). Optional keys (jerk, mu_static, ...)
// have an on/off box: off means the key is absent from the config (the CLI's "none").

export const DIMENSION = {
  none: 'none', length: 'length', time: 'time', velocity: 'velocity',
  acceleration: 'acceleration', jerk: 'jerk',
};

// kind: 'number' (slider + box), 'select', 'list' (comma-separated numbers, kept as text).
// group: the panel. when(state): shown or not.
// range: [min, max] of the slider in [-]; log: slider on a logarithmic scale. siOnly: shown in
// both systems (the readouts use it) but part of the config in SI runs only.
const threePhase = (s) => s.profile === 'three-phase';
const twoRegion = (s) => s.friction === 'two-region';

export const CONTROLS = [
  { key: 'units', label: 'units', kind: 'select', group: 'run', options: ['dimensionless', 'si'], def: 'dimensionless' },
  { key: 'mass', label: 'mass m', kind: 'number', group: 'scales', dim: 'mass', range: [0.001, 10], log: true, def: 1, siOnly: true, unit: 'kg' },
  { key: 'g', label: 'gravity g', kind: 'number', group: 'scales', dim: 'gravity', range: [1, 20], def: 9.81, siOnly: true, unit: 'm/s²' },
  { key: 'length_scale', label: 'length scale L', kind: 'number', group: 'scales', dim: 'scale', range: [1e-4, 1e-1], log: true, def: 1e-3, siOnly: true, unit: 'm' },

  { key: 'profile', label: 'family', kind: 'select', group: 'profile', options: ['three-phase', 'fourier', 'quadratic-sequence', 'piecewise-linear'], def: 'three-phase' },
  { key: 'period', label: 'period Δt', kind: 'number', group: 'profile', dim: 'time', range: [0.2, 5], def: 1, when: (s) => s.profile !== 'quadratic-sequence' },
  { key: 'stroke', label: 'stroke Δy', kind: 'number', group: 'profile', dim: 'length', range: [0.005, 0.5], log: true, def: 0.084, when: threePhase },
  { key: 'a2', label: "y2''", kind: 'number', group: 'profile', dim: 'acceleration', range: [0.5, 6], def: 2.3, when: threePhase },
  { key: 'a3', label: "y3''", kind: 'number', group: 'profile', dim: 'acceleration', range: [0.1, 6], def: 1.3, when: threePhase },
  { key: 'jerk', label: 'jerk j', kind: 'number', group: 'profile', dim: 'jerk', range: [5, 2000], log: true, def: 200, optional: true, when: threePhase },
  // Lists (comma-separated): the quadratic sequence's segments (its period is their sum) and the
  // piecewise-linear acceleration's breakpoints; both families' accelerations are the config's
  // `accelerations` (configKey), each with its own default.
  { key: 'durations', label: 'durations', kind: 'list', group: 'profile', dim: 'time', def: '0.3,0.2,0.5', when: (s) => s.profile === 'quadratic-sequence' },
  { key: 'accelerations', label: "y'' per segment", kind: 'list', group: 'profile', dim: 'acceleration', def: '2,-6,1.2', when: (s) => s.profile === 'quadratic-sequence' },
  { key: 'times', label: 'breakpoints t', kind: 'list', group: 'profile', dim: 'time', def: '0,0.2,0.5', when: (s) => s.profile === 'piecewise-linear' },
  { key: 'pl_accelerations', configKey: 'accelerations', label: "y'' at breakpoints", kind: 'list', group: 'profile', dim: 'acceleration', def: '3,-5.8,1', when: (s) => s.profile === 'piecewise-linear' },
  { key: 'amplitude', label: 'amplitude A₁', kind: 'number', group: 'profile', dim: 'length', range: [0.005, 0.5], log: true, def: 0.05, when: (s) => s.profile === 'fourier' },

  { key: 'mu', label: 'μ (kinetic)', kind: 'number', group: 'law', dim: 'none', range: [0.05, 1], def: 0.3 },
  { key: 'mu_static', label: 'μ_s (static)', kind: 'number', group: 'law', dim: 'none', range: [0.05, 1.5], def: 0.36, optional: true },
  { key: 'mu_backward', label: 'μ backward', kind: 'number', group: 'law', dim: 'none', range: [0.05, 1], def: 0.3, optional: true },
  { key: 'stribeck_velocity', label: 'Stribeck v_s', kind: 'number', group: 'law', dim: 'velocity', range: [0.001, 1], log: true, def: 0.05, optional: true },

  { key: 'friction', label: 'table', kind: 'select', group: 'table', options: ['two-region', 'uniform'], def: 'two-region' },
  { key: 'x_mu', label: 'x_μ', kind: 'number', group: 'table', dim: 'length', range: [0, 2], def: 0.5, when: twoRegion },
  { key: 'width', label: 'width w', kind: 'number', group: 'table', dim: 'length', range: [0.005, 0.5], log: true, def: 0.05, when: twoRegion },
  { key: 'c_mu', label: 'c_μ = μ₂/μ₁', kind: 'number', group: 'table', dim: 'none', range: [1.01, 5], def: 2.5, when: twoRegion },

  { key: 'x0', label: 'x₀', kind: 'number', group: 'run', dim: 'length', range: [-1, 2], def: 0 },
  { key: 'v0', label: "x'₀", kind: 'number', group: 'run', dim: 'velocity', range: [-1, 1], def: 0 },
  { key: 'periods', label: 'periods shown', kind: 'number', group: 'run', dim: 'none', range: [1, 40], def: 4, integer: true },
];

export const BY_KEY = Object.fromEntries(CONTROLS.map((c) => [c.key, c]));

// The map's own settings (not config keys): grid size per axis and the plotted quantity.
export const MAP_DEFAULTS = { map_n: 100, map_quantity: 'v_bar', a2_lo: 1.05, a2_hi: 5, a3_lo: 0.2, a3_hi: 5 };
export const STOP_DEFAULTS = { max_periods: 2000 };
