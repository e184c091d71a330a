// The table motion and the part's response over a few periods (simulate), stick shaded, and the
// steady state's census (steady: motion case, stick/slip pattern, v̄, f, x'_0s).
import { View } from './view.js';
import { timeChart } from './plots.js';
import { csvOf, downloadText, downloadUplotPng } from './export.js';
import { exact } from './units.js';

export class ResponseView extends View {
  constructor(root) {
    super(root);
    this.trajectory = null;
    const stick = () => (this.trajectory ? this.trajectory.stick : null);
    this.positions = timeChart(root.querySelector('.chart-positions'), 'positions (stick shaded)', 't',
      [{ label: 'x (object, relative)', stroke: '#c0392b' }, { label: 'y (table)', stroke: '#2c3e50' }], stick);
    this.velocities = timeChart(root.querySelector('.chart-velocities'), 'velocities and table acceleration', 't',
      [{ label: "x' (relative)", stroke: '#c0392b' }, { label: "y'", stroke: '#2c3e50' },
       { label: "y''", stroke: '#27ae60', scale: 'a', dash: [4, 3] }], stick,
      [{}, { scale: 'a', side: 1, grid: { show: false } }]);
    root.querySelector('.export-csv').addEventListener('click', () => this.exportCsv());
    root.querySelector('.export-png').addEventListener('click', () => {
      downloadUplotPng('response-positions.png', this.positions);
      downloadUplotPng('response-velocities.png', this.velocities);
    });
  }

  // Draws a run (simulate's result) and the steady state's report; `unitLabel(dim)` labels values.
  show(run, steady, unitLabel) {
    const tr = run.trajectory;
    this.trajectory = tr;
    this.positions.setData([tr.t, tr.x, tr.y]);
    this.velocities.setData([tr.t, tr.x_dot, tr.y_dot, tr.y_ddot]);
    const set = (name, text) => this.setNumber(name, text);
    set('v_bar', exact(steady.v_bar));
    set('f', exact(steady.f));
    set('case', steady.case === 0 ? '0 (no physical profile)' : `${steady.case} (${steady.case_name ?? ''})`);
    set('pattern', steady.pattern ?? 'none');
    set('x_dot_0s', exact(steady.x_dot_0s));
    set('end_position', exact(run.final.x));
    set('mean_velocity', exact(run.mean_velocity_last_period));
    set('stick_fraction', exact(run.stick_fraction));
    this.setUnits(unitLabel);
    this.solved();
  }

  exportCsv() {
    if (!this.trajectory) return;
    const tr = this.trajectory;
    // The CLI's trajectory CSV (io/trajectory_csv.hpp): t,x,x_dot,y,y_dot,y_ddot,stick.
    downloadText('response.csv', csvOf({ t: tr.t, x: tr.x, x_dot: tr.x_dot, y: tr.y, y_dot: tr.y_dot, y_ddot: tr.y_ddot, stick: tr.stick }));
  }
}
