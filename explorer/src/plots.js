// uPlot helpers shared by the time-series views: stick intervals shaded, fixed size.
import uPlot from 'uplot';

// Shades the samples where stick[i] = 1 (the object at rest on the table) behind the series.
function stickShading(stickOf) {
  return {
    hooks: {
      drawClear: [
        (u) => {
          const t = u.data[0], stick = stickOf();
          if (!stick || !t || t.length === 0) return;
          const ctx = u.ctx;
          ctx.save();
          ctx.fillStyle = 'rgba(70, 130, 180, 0.18)';
          for (let i = 0; i < t.length; ) {
            if (!stick[i]) { ++i; continue; }
            let j = i;
            while (j + 1 < t.length && stick[j + 1]) ++j;
            const x0 = u.valToPos(t[i], 'x', true), x1 = u.valToPos(t[j], 'x', true);
            ctx.fillRect(x0, u.bbox.top, Math.max(1, x1 - x0), u.bbox.height);
            i = j + 1;
          }
          ctx.restore();
        },
      ],
    },
  };
}

// Tick labels that stay readable at any scale (SI lengths are ~1e-4 m): 4 significant digits,
// exponent form below 1e-3.
function tickValues(u, ticks) {
  return ticks.map((v) => {
    if (v === null || v === undefined) return '';
    if (v !== 0 && Math.abs(v) < 1e-3) return v.toExponential(1);
    return Number(v.toPrecision(4)).toString();
  });
}

// A chart of series over t; `series` = [{label, stroke, scale?, dash?}], `stickOf` returns the
// stick flags of the data shown (or null).
export function timeChart(el, title, xLabel, series, stickOf, axes = []) {
  const opts = {
    title,
    width: 640,
    height: 240,
    plugins: [stickShading(stickOf)],
    scales: { x: { time: false } },
    series: [{ label: xLabel }, ...series.map((s) => ({ width: 1.5, ...s }))],
    axes: [{ label: xLabel, values: tickValues }, ...(axes.length ? axes : [{}]).map((a) => ({ values: tickValues, size: 60, ...a }))],
    legend: { live: false },
  };
  return new uPlot(opts, [[], ...series.map(() => [])], el);
}
