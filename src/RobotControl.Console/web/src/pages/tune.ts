import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import { api, type ControllerView, type MotorView } from '../api';
import { el, fmt } from '../dom';
import { degPerRad } from '../angles';
import { homeAndRelease, jogControls, parameterEditor, pedalButtons, setpointControls, showParameters } from '../motorcontrols';
import { SignalStream, type Frame } from '../stream';

/** The history the plot keeps, seconds. */
const historySeconds = 10;

// Tuning (one motor, in the manner of a PID tab): its desired and measured axis output over the last seconds, beside
// its live values, jog, setpoint, release and its parameters (the P gain among them). "Desired" is the server's: the
// goal the motor follows (its jog or setpoint target while in manual, else the control loop's), never rebuilt here.
export function tunePage(root: HTMLElement): () => void {
  const picker = el('select', { 'aria-label': 'joint', 'data-testid': 'tune-motor' });
  const holder = el('div', { class: 'plot', 'data-testid': 'tune-plot', role: 'figure', 'aria-label': 'desired and measured position, degrees, last 10 s' });
  const count = el('span', { 'data-testid': 'tune-samples' }, '0 samples');
  const facts = el('dl', { class: 'tune-facts' });
  const controls = el('div', { class: 'tune-controls' });
  root.append(el('div', { class: 'toolbar' }, el('label', {}, 'joint ', picker), ...pedalButtons(), count),
    el('div', { class: 'tune' }, el('div', { class: 'tune-plot' }, holder), el('div', {}, facts, controls)));

  let motor: MotorView | null = null;
  let times: number[] = [];
  let desired: number[] = [];
  let measured: number[] = [];
  let plot: uPlot | null = null;
  let dirty = false;

  const stream = new SignalStream((names, frame: Frame) => {
    if (!motor || names[0] !== motor.desiredSignal) return;
    if (frame.t.length > 0 && times.length > 0 && frame.t[0] < times[times.length - 1]) {
      times = []; desired = []; measured = []; // a new timeline (the server's session began again)
    }
    times.push(...frame.t);
    desired.push(...frame.v[0].map((v) => v * degPerRad));
    measured.push(...frame.v[1].map((v) => v * degPerRad));
    const last = times[times.length - 1] ?? 0;
    let drop = 0;
    while (drop < times.length && times[drop] < last - historySeconds) drop++;
    if (drop > 0) { times = times.slice(drop); desired = desired.slice(drop); measured = measured.slice(drop); }
    dirty = true;
  });
  const redraw = setInterval(() => { if (dirty) { dirty = false; draw(); } }, 50);

  function draw(): void {
    count.textContent = `${times.length} samples`;
    // The page's test hook: the last plotted values, as drawn.
    holder.dataset.desiredDeg = String(desired[desired.length - 1] ?? '');
    holder.dataset.measuredDeg = String(measured[measured.length - 1] ?? '');
    plot?.setData([times, desired, measured] as uPlot.AlignedData);
  }

  function choose(m: MotorView): void {
    motor = m;
    times = []; desired = []; measured = [];
    plot?.destroy();
    plot = new uPlot({
      width: Math.max(400, holder.clientWidth || 700),
      height: 360,
      scales: { x: { time: false } },
      axes: [{ label: 'session time (s)' }, { label: `${m.name} (deg)` }],
      series: [{ label: 't (s)' },
        { label: 'desired (deg)', stroke: '#d62728', width: 1.5 },
        { label: 'measured (deg)', stroke: '#1f77b4', width: 1.5 }],
    }, [times, desired, measured] as uPlot.AlignedData, holder);
    stream.subscribe([m.desiredSignal, m.measuredSignal]);
    controls.replaceChildren(
      el('h3', {}, `${m.name} (module channel ${m.channel})`),
      el('div', { class: 'jog' }, el('span', {}, 'jog '), ...jogControls(m)),
      el('div', {}, el('span', {}, 'setpoint ° '), ...setpointControls(m), ...homeAndRelease(m)),
      el('div', { class: 'params' }, ...m.parameters.map((p) => parameterEditor(m, p))));
  }

  function fact(label: string, field: string): HTMLElement[] {
    return [el('dt', {}, label), el('dd', { 'data-field': field, 'data-testid': `tune-${field}` })];
  }
  facts.append(...fact('position °', 'position'), ...fact('desired °', 'desired'), ...fact("graph's command °", 'command'),
    ...fact('current A', 'current'), ...fact('PWM', 'pwm'), ...fact('torque', 'torque'), ...fact('errors', 'errors'));

  function show(m: MotorView): void {
    const set = (field: string, text: string) => {
      const e = facts.querySelector(`[data-field="${field}"]`);
      if (e && e.textContent !== text) e.textContent = text;
    };
    set('position', fmt(m.positionDeg, 2));
    set('desired', fmt(m.desiredDeg, 2));
    set('command', fmt(m.loopCommandDeg, 2));
    set('current', fmt(m.currentA, 3));
    set('pwm', String(m.pwm));
    set('torque', `${m.torqueOn ? 'on' : 'off'}${m.manual ? ' · manual' : ''}`);
    set('errors', m.errors.join(', ') || '—');
    showParameters(controls, m);
  }

  async function refresh(): Promise<void> {
    const motors = (await api<ControllerView[]>('GET', '/controllers')).flatMap((c) => c.motors);
    const names = motors.map((m) => m.name).join();
    if (Array.from(picker.options).map((o) => o.value).join() !== names) {
      const keep = picker.value;
      picker.replaceChildren(...motors.map((m) => el('option', { value: m.name }, m.name)));
      if (motors.some((m) => m.name === keep)) picker.value = keep;
    }
    const current = motors.find((m) => m.name === picker.value);
    if (!current) return;
    if (current.name !== motor?.name) choose(current);
    show(current);
  }

  picker.addEventListener('change', () => void refresh());
  const timer = setInterval(() => void refresh().catch(() => undefined), 300);
  void refresh().catch(() => undefined);
  return () => { clearInterval(timer); clearInterval(redraw); stream.close(); plot?.destroy(); };
}
