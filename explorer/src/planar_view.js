// A planar run (`selfalign planar simulate`; docs/planar.md) from a config given as text: the
// part's path on the table, its orientation, and the step census (stick, pivot, slip).
import { View } from './view.js';
import Plotly from 'plotly.js-dist-min';
import { csvOf, downloadText, downloadPlotlyPng } from './export.js';
import { exact } from './units.js';
import example from '../../examples/planar.toml';

// examples/planar.toml, shortened from 200 to 20 periods (about 0.1 s in the browser).
export const PLANAR_EXAMPLE = example.replace(/^periods = 200\b/m, 'periods = 20');

export class PlanarView extends View {
  constructor(root, onRun) {
    super(root);
    this.result = null;
    this.text = root.querySelector('.planar-config');
    this.format = root.querySelector('.planar-format');
    this.div = root.querySelector('.chart-planar');
    if (!this.text.value) this.text.value = PLANAR_EXAMPLE;
    root.querySelector('.planar-run').addEventListener('click', () => onRun());
    root.querySelector('.export-csv').addEventListener('click', () => this.exportCsv());
    root.querySelector('.export-png').addEventListener('click', () => downloadPlotlyPng(Plotly, 'planar.png', this.div));
  }

  async solve(core) {
    const t0 = performance.now();
    const r = core.planar(this.text.value, this.format.value);
    this.result = r;
    const tr = r.trajectory, u = r.units === 'si' ? '[m]' : '[-]';
    await Plotly.react(this.div, [
      { x: tr.x, y: tr.y, mode: 'lines', name: 'path on the table', line: { color: '#c0392b' } },
      { x: [tr.x[0]], y: [tr.y[0]], mode: 'markers', name: 'start', marker: { color: '#2c3e50', size: 8 } },
      { x: [r.end_pose.x], y: [r.end_pose.y], mode: 'markers', name: 'end', marker: { color: '#8e44ad', size: 9, symbol: 'x' } },
    ], {
      width: 520, height: 420, margin: { l: 70, r: 10, t: 30, b: 50 },
      title: { text: 'the part\'s reference point on the table', font: { size: 13 } },
      xaxis: { title: { text: `x ${u}` } }, yaxis: { title: { text: `y ${u}` }, scaleanchor: 'x' },
      legend: { x: 0.02, y: 0.98 },
    }, { displayModeBar: false });
    const set = (name, text) => this.setNumber(name, text);
    set('end_x', exact(r.end_pose.x));
    set('end_y', exact(r.end_pose.y));
    set('end_angle', exact(r.end_pose.angle_rad));
    set('census', `stick ${r.census.stick}, pivot ${r.census.pivot}, slip ${r.census.slip}`);
    set('method', r.method);
    set('unused', r.unused_keys.length ? r.unused_keys.join(', ') : 'none');
    this.solved();
    return performance.now() - t0;
  }


  exportCsv() {
    if (this.result) downloadText('planar.csv', csvOf(this.result.trajectory));
  }
}
