// CSV and PNG export of each view: a download made in the page (no server).

export function download(name, href) {
  const a = document.createElement('a');
  a.href = href;
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
}

export function downloadText(name, text) {
  const url = URL.createObjectURL(new Blob([text], { type: 'text/csv' }));
  download(name, url);
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

// Columns (equal-length arrays) as CSV with a header; numbers in shortest round-trip form,
// absent values empty.
export function csvOf(columns) {
  const keys = Object.keys(columns);
  const n = columns[keys[0]].length;
  const rows = [keys.join(',')];
  for (let i = 0; i < n; ++i)
    rows.push(keys.map((k) => (columns[k][i] === null ? '' : String(columns[k][i]))).join(','));
  return rows.join('\n') + '\n';
}

// A uPlot chart's canvas as PNG.
export function downloadUplotPng(name, plot) {
  download(name, plot.ctx.canvas.toDataURL('image/png'));
}

// A plotly chart as PNG.
export async function downloadPlotlyPng(Plotly, name, div) {
  download(name, await Plotly.toImage(div, { format: 'png', width: 900, height: 600 }));
}
