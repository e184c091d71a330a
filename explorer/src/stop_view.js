// Stopping at the friction step (Sect. 7): the run into the transition region, its end position
// and x_stick,min (eq. 41), and the stick-position map of eq. (59) with the run's stick
// positions accumulating at its fixed point (eq. 60) drawn as a cobweb.
import { View } from './view.js';
import Plotly from 'plotly.js-dist-min';
import { timeChart } from './plots.js';
import { csvOf, downloadText, downloadUplotPng, downloadPlotlyPng } from './export.js';
import { exact } from './units.js';

export class StopView extends View {
  constructor(root) {
    super(root);
    this.report = null;
    this.chart = timeChart(root.querySelector('.chart-stop'), 'stopping run (stick shaded)', 't',
      [{ label: 'x', stroke: '#c0392b' }, { label: 'x_μ', stroke: '#7f8c8d', dash: [6, 4] },
       { label: 'x_stick,min', stroke: '#8e44ad', dash: [2, 3] }],
      () => (this.report ? this.report.trajectory.stick : null));
    this.mapDiv = root.querySelector('.chart-stickmap');
    root.querySelector('.export-csv').addEventListener('click', () => this.exportCsv());
    root.querySelector('.export-png').addEventListener('click', () => {
      downloadUplotPng('stop-trajectory.png', this.chart);
      downloadPlotlyPng(Plotly, 'stop-map.png', this.mapDiv);
    });
  }

  async show(report, unitLabel) {
    this.report = report;
    const tr = report.trajectory, n = tr.t.length;
    const flat = (v) => new Array(n).fill(v);
    this.chart.setData([tr.t, tr.x, flat(report.x_mu), flat(report.x_stick_min)]);
    const set = (name, text) => this.setNumber(name, text);
    set('stop', report.stop + (report.accumulation_proven ? ' (proven by eq. 59)' : ''));
    set('end_position', exact(report.end_position));
    set('x_stick_min', exact(report.x_stick_min));
    set('process_time', report.stop === 'accumulation' ? 'inf (accumulation)' : exact(report.process_time));
    set('entry_time', exact(report.entry_time));
    set('sticks', String(report.stick_positions.length));
    this.setUnits(unitLabel);
    await this.drawMap(report, unitLabel('length'));
    this.solved();
  }

  async drawMap(report, len) {
    const m = report.map;
    if (!m) {
      await Plotly.react(this.mapDiv, [], { width: 480, height: 400,
        title: { text: 'eq. (59) needs the three-phase profile on the two-region table', font: { size: 12 } } });
      return;
    }
    // The cobweb: (x1, x1) -> (x1, x2) -> (x2, x2) -> ...
    const s = report.stick_positions, cx = [], cy = [];
    for (let k = 0; k + 1 < s.length; ++k) { cx.push(s[k], s[k]); cy.push(s[k], s[k + 1]); }
    if (s.length) { cx.push(s[s.length - 1]); cy.push(s[s.length - 1]); }
    const traces = [
      { x: m.x_n, y: m.x_next, mode: 'lines', name: 'x_{n+1}(x_n), eq. 59', line: { color: '#2c3e50' } },
      { x: [m.x_n[0], m.x_n[m.x_n.length - 1]], y: [m.x_n[0], m.x_n[m.x_n.length - 1]], mode: 'lines', name: 'x_{n+1} = x_n', line: { color: '#95a5a6', dash: 'dot' } },
      { x: cx, y: cy, mode: 'lines+markers', name: 'stick positions', line: { color: '#c0392b' }, marker: { size: 4 } },
      { x: [m.fixed_point], y: [m.fixed_point], mode: 'markers', name: 'fixed point, eq. 60', marker: { size: 10, symbol: 'circle-open', color: '#8e44ad' } },
    ];
    await Plotly.react(this.mapDiv, traces, {
      width: 480, height: 400, margin: { l: 60, r: 10, t: 30, b: 50 },
      title: { text: 'stick-position map and its accumulation', font: { size: 13 } },
      xaxis: { title: { text: `x_n ${len}` } }, yaxis: { title: { text: `x_{n+1} ${len}` } },
      legend: { x: 0.02, y: 0.98, font: { size: 10 } },
    }, { displayModeBar: false });
  }


  exportCsv() {
    if (!this.report) return;
    const tr = this.report.trajectory;
    // As `selfalign stop --out`: t,x,x_dot,stick.
    downloadText('stop.csv', csvOf({ t: tr.t, x: tr.x, x_dot: tr.x_dot, stick: tr.stick }));
  }
}
