// The v̄ (or f) map over (y2'', y3'') with the motion cases' regions (sweep accelerations), the
// current point marked; a click on a cell loads that point into the response view.
import { View } from './view.js';
import Plotly from 'plotly.js-dist-min';
import { csvOf, downloadText, downloadPlotlyPng } from './export.js';

export class MapView extends View {
  constructor(root, onPick) {
    super(root);
    this.div = root.querySelector('.chart-map');
    this.cells = null;
    this.onPick = onPick;
    root.querySelector('.export-csv').addEventListener('click', () => this.exportCsv());
    root.querySelector('.export-png').addEventListener('click', () => downloadPlotlyPng(Plotly, 'map.png', this.div));
  }

  // Draws `cells` (the core's sweep) with `quantity` ('v_bar' | 'f') and the point (a2, a3).
  // Resolves when plotly has drawn.
  async show(cells, quantity, a2, a3, unitLabel) {
    this.cells = cells;
    const n2 = cells.a2.length, n3 = cells.a3.length;
    const grid = (key) => {
      const z = [];
      for (let j = 0; j < n3; ++j) {
        const row = new Array(n2);
        for (let i = 0; i < n2; ++i) row[i] = cells[key][i * n3 + j];  // a2 outer (wasm/api.cpp)
        z.push(row);
      }
      return z;
    };
    const acc = unitLabel('acceleration');
    const traces = [
      { type: 'heatmap', x: cells.a2, y: cells.a3, z: grid(quantity), colorscale: 'Viridis',
        colorbar: { title: { text: quantity === 'v_bar' ? `v̄ ${unitLabel('velocity')}` : 'f [-]' } },
        hovertemplate: `y2'' %{x}<br>y3'' %{y}<br>${quantity} %{z}<extra></extra>` },
      { type: 'contour', x: cells.a2, y: cells.a3, z: grid('case'), showscale: false, hoverinfo: 'skip',
        contours: { coloring: 'lines', start: 0.5, end: 5.5, size: 1, showlabels: false },
        line: { color: 'white', width: 1.5 } },
      { type: 'scatter', mode: 'markers', x: [a2], y: [a3], hoverinfo: 'skip',
        marker: { symbol: 'x', size: 12, color: '#e74c3c' }, showlegend: false },
    ];
    const layout = {
      width: 640, height: 480, margin: { l: 60, r: 20, t: 30, b: 50 },
      title: { text: `${quantity === 'v_bar' ? 'v̄' : 'f'} over (y2'', y3''); lines: motion-case boundaries`, font: { size: 13 } },
      xaxis: { title: { text: `y2'' ${acc}` } }, yaxis: { title: { text: `y3'' ${acc}` } },
    };
    await Plotly.react(this.div, traces, layout, { displayModeBar: false, staticPlot: false });
    if (!this.listening) {
      this.listening = true;
      this.div.on('plotly_click', (e) => {
        const p = e.points && e.points[0];
        if (p) this.onPick(p.x, p.y);
      });
    }
    // A map without one physical cell is a result (case 0 everywhere), said in words.
    if (cells.case.every((c) => c === 0))
      this.fail("every cell is case 0 (no physical profile): need 1/y2'' + 1/y3'' <= period^2/(8 stroke)");
    else this.solved();
  }

  // Moves the marker only (a2, a3 changed; the map itself does not depend on them).
  mark(a2, a3) {
    if (this.cells) Plotly.restyle(this.div, { x: [[a2]], y: [[a3]] }, [2]);
  }


  exportCsv() {
    if (!this.cells) return;
    const c = this.cells, a2 = [], a3 = [];
    for (const x of c.a2) for (const y of c.a3) { a2.push(x); a3.push(y); }
    // As `selfalign sweep accelerations --out cells.csv`, a2 outer.
    downloadText('map.csv', csvOf({ a2, a3, case_a_priori: c.case_a_priori, case: c.case, v_bar: c.v_bar, f: c.f }));
  }
}
