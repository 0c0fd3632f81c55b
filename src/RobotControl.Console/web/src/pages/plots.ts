import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import { api, markFirstValue, onRestart } from '../api';
import { el, button } from '../dom';
import { displayFactor, displayUnit, type AngleUnit } from '../angles';
import { SignalStream, type Frame } from '../stream';

interface Signal { name: string; unit: string }

// Plots: any signal live (uPlot), several per plot, pause, time window, CSV export of the window. Angles (signals the
// server gives in "rad") are shown in degrees unless the operator picks radians; the legend and the CSV say which.
export function plotsPage(root: HTMLElement): () => void {
  const filter = el('input', { placeholder: 'filter signals', 'aria-label': 'filter signals' });
  const picker = el('select', { multiple: 'multiple', size: '12', 'aria-label': 'signals', 'data-testid': 'signal-picker' });
  const windowSelect = el('select', { 'aria-label': 'time window' }, ...[5, 10, 30, 60].map((s) => el('option', { value: String(s) }, `${s} s`)));
  const anglesSelect = el('select', { 'aria-label': 'angles in', 'data-testid': 'angle-unit' }, el('option', { value: 'deg' }, 'degrees'), el('option', { value: 'rad' }, 'radians'));
  const pause = el('input', { type: 'checkbox', 'aria-label': 'pause' });
  const count = el('span', { 'data-testid': 'plot-samples' }, '0 samples');
  const holder = el('div', { class: 'plot', 'data-testid': 'plot' });
  root.append(el('div', { class: 'plots' },
    el('div', { class: 'picker' }, filter, picker, el('small', {}, 'Ctrl/Shift-click: several signals per plot')),
    el('div', {},
      el('div', { class: 'toolbar' }, el('label', {}, 'window ', windowSelect), el('label', {}, 'angles ', anglesSelect), el('label', {}, pause, ' pause'),
        button('Export CSV', exportCsv, { 'data-testid': 'export-csv' }), count),
      holder)));

  let signals: Signal[] = [];
  let chosen: string[] = [];
  let times: number[] = [];
  let series: number[][] = []; // as the server sends them (angles in radians)
  let plot: uPlot | null = null;
  const angles = (): AngleUnit => anglesSelect.value as AngleUnit;
  const unitOf = (name: string): string => signals.find((s) => s.name === name)?.unit ?? '';
  const shown = (): number[][] => series.map((s, i) => { const f = displayFactor(unitOf(chosen[i]), angles()); return f === 1 ? s : s.map((v) => v * f); });
  const label = (name: string): string => { const u = displayUnit(unitOf(name), angles()); return u ? `${name} (${u})` : name; };

  const stream = new SignalStream((names, frame: Frame) => {
    if (names.join() !== chosen.join()) return;
    // Rows from before the last one plotted start a new timeline (the replay was moved back, or the server restarted
    // and its session began again): the old rows go, so the plot never mixes two timelines.
    if (frame.t.length > 0 && times.length > 0 && frame.t[0] < times[times.length - 1]) {
      times = [];
      series = series.map(() => []);
    }
    times.push(...frame.t);
    frame.v.forEach((v, i) => series[i]?.push(...v));
    trim();
    dirty = true;
  });
  // Redraw at most 20 times a second, whatever the stream's frame rate.
  let dirty = false;
  const redraw = setInterval(() => { if (dirty && !pause.checked) { dirty = false; draw(); } }, 50);

  function trim(): void {
    const span = Number(windowSelect.value);
    const last = times[times.length - 1] ?? 0;
    let drop = 0;
    while (drop < times.length && times[drop] < last - span) drop++;
    if (drop > 0) {
      times = times.slice(drop);
      series = series.map((s) => s.slice(drop));
    }
  }

  function draw(): void {
    count.textContent = `${times.length} samples`;
    plot?.setData([times, ...shown()] as uPlot.AlignedData);
    if (times.length > 0) markFirstValue(root);
  }

  function rebuild(): void {
    chosen = Array.from(picker.selectedOptions).map((o) => o.value);
    times = [];
    series = chosen.map(() => []);
    makePlot();
    stream.subscribe(chosen);
  }

  /** A new plot of the chosen signals over the rows kept, in the units shown. */
  function makePlot(): void {
    plot?.destroy();
    plot = new uPlot({
      width: Math.max(400, holder.clientWidth || 800),
      height: 380,
      scales: { x: { time: false } },
      axes: [{ label: 'session time (s)' }, {}],
      series: [{ label: 't (s)' }, ...chosen.map((name, i) => ({
        label: label(name),
        stroke: ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#17becf'][i % 6],
        width: 1.5,
      }))],
    }, [times, ...shown()] as uPlot.AlignedData, holder);
  }

  function exportCsv(): void {
    const header = ['time_s', ...chosen.map(label)].join(',');
    const values = shown();
    const rows = times.map((t, r) => [t, ...values.map((s) => s[r])].join(','));
    const blob = new Blob([[header, ...rows].join('\n') + '\n'], { type: 'text/csv' });
    const a = el('a', { href: URL.createObjectURL(blob), download: 'signals.csv' });
    a.click();
    URL.revokeObjectURL(a.href);
  }

  function fill(): void {
    const f = filter.value.toLowerCase();
    const selected = new Set(Array.from(picker.selectedOptions).map((o) => o.value));
    picker.replaceChildren(...signals.filter((s) => s.name.toLowerCase().includes(f) || selected.has(s.name))
      .map((s) => { const o = el('option', { value: s.name }, `${s.name}${s.unit ? ` (${s.unit})` : ''}`); o.selected = selected.has(s.name); return o; }));
  }

  // A restarted server: none of the old run's samples stay (its new rows may even lie ahead of them in time).
  const leaveRestart = onRestart(() => {
    times = [];
    series = series.map(() => []);
    draw();
  });

  filter.addEventListener('input', fill);
  picker.addEventListener('change', rebuild);
  windowSelect.addEventListener('change', () => { trim(); draw(); });
  anglesSelect.addEventListener('change', makePlot);
  void api<Signal[]>('GET', '/signals').then((s) => {
    signals = s;
    fill();
    const first = Array.from(picker.options).find((o) => o.value.endsWith('.position'));
    if (first) { first.selected = true; rebuild(); }
  });
  return () => { clearInterval(redraw); leaveRestart(); stream.close(); plot?.destroy(); };
}
