// The vibratory feeder's regime chart (`selfalign regimes`; docs/feeder.md) over vibration
// angle x machine number K = a0 w^2 / g: the closed-form regime of each cell (stick, forward,
// backward, both, hopping) or the simulated dimensionless conveying speed v / (a0 w cos psi).
import { View } from './view.js';
import Plotly from 'plotly.js-dist-min';
import { csvOf, downloadText, downloadPlotlyPng } from './export.js';

const REGIMES = ['stick', 'forward', 'backward', 'both', 'hopping'];
const REGIME_COLOURS = ['#95a5a6', '#27ae60', '#c0392b', '#f39c12', '#8e44ad'];

// The request's inputs: the CLI's flags with '_' (wasm/api.cpp regimes), their defaults.
export const FEEDER_DEFAULTS = {
  mu_static: 0.5, mu_kinetic: 0.4, incline: 0, angle_min: 0, angle_max: 1.2, angles: 30,
  k_min: 0.1, k_max: 10, machine_numbers: 30, periods: 10,
};

export class FeederView extends View {
  constructor(root, request) {
    super(root);
    this.request = request;  // the page state's feeder part, edited in place
    this.div = root.querySelector('.chart-regimes');
    this.result = null;
    for (const el of root.querySelectorAll('[data-feeder]')) {
      if (el.dataset.feeder !== 'quantity') el.value = String(request[el.dataset.feeder]);
      el.addEventListener('change', () => {
        const v = el.tagName === 'SELECT' ? el.value : Number(el.value);
        if (el.dataset.feeder !== 'quantity') this.request[el.dataset.feeder] = v;
        this.onChange?.();
      });
    }
    root.querySelector('.export-csv').addEventListener('click', () => this.exportCsv());
    root.querySelector('.export-png').addEventListener('click', () => downloadPlotlyPng(Plotly, 'regimes.png', this.div));
  }

  quantity() { return this.root.querySelector('[data-feeder="quantity"]').value; }

  // Solves with the core and draws; resolves when plotly has drawn. Returns the time [ms].
  async solve(core) {
    const t0 = performance.now();
    const r = core.regimes(this.request);
    this.result = r;
    const rows = r.rows, nK = this.request.machine_numbers, nA = this.request.angles;
    const angles = [], ks = [];
    for (let i = 0; i < nA; ++i) angles.push(rows.vibration_angle_rad[i * nK]);
    for (let j = 0; j < nK; ++j) ks.push(rows.machine_number[j]);
    const speed = this.quantity() === 'speed';
    const z = [], text = [];
    for (let j = 0; j < nK; ++j) {  // machine number fastest (feeder_regime_chart)
      const zr = [], tr = [];
      for (let i = 0; i < nA; ++i) {
        const k = i * nK + j;
        zr.push(speed ? rows.dimensionless_speed[k] : REGIMES.indexOf(rows.regime[k]));
        tr.push(`${rows.regime[k]}; speed ${rows.dimensionless_speed[k]}; first event ${rows.first_event[k]}`);
      }
      z.push(zr);
      text.push(tr);
    }
    const discrete = REGIMES.flatMap((_, k) => [[k / 5, REGIME_COLOURS[k]], [(k + 1) / 5, REGIME_COLOURS[k]]]);
    const trace = speed
      ? { type: 'heatmap', x: angles, y: ks, z, text, colorscale: 'Viridis', hovertemplate: 'ψ %{x} rad<br>K %{y}<br>%{text}<extra></extra>',
          colorbar: { title: { text: 'v / (a0 ω cos ψ)' } } }
      : { type: 'heatmap', x: angles, y: ks, z, text, zmin: -0.5, zmax: 4.5, colorscale: discrete,
          hovertemplate: 'ψ %{x} rad<br>K %{y}<br>%{text}<extra></extra>',
          colorbar: { tickvals: [0, 1, 2, 3, 4], ticktext: REGIMES } };
    await Plotly.react(this.div, [trace], {
      width: 640, height: 460, margin: { l: 60, r: 20, t: 30, b: 50 },
      title: { text: speed ? 'conveying speed' : 'regimes (closed-form onsets)', font: { size: 13 } },
      xaxis: { title: { text: 'vibration angle ψ [rad]' } },
      yaxis: { title: { text: 'machine number K = a0 ω²/g' }, type: 'log' },
    }, { displayModeBar: false });
    const set = (name, text) => this.setNumber(name, text);
    set('regimes', REGIMES.map((k) => `${k} ${r.regimes[k]}`).join(', '));
    set('failed', String(r.failed));
    this.solved();
    return performance.now() - t0;
  }


  exportCsv() {
    if (this.result) downloadText('regimes.csv', csvOf(this.result.rows));  // `regimes --csv`'s columns
  }
}
