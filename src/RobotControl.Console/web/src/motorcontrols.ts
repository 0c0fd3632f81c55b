// A motor's controls as the bus page and the tuning page both show them: pedal, jog, setpoint, home, release (asking
// first when it would move the joint), and its persistent parameters (P gain and the others). One copy, two pages.
import { api, act, show, type ControllerView, type MotorView, type ParameterSpec } from './api';
import { el, button, fmt } from './dom';

/** Controls that need the operator role (role.ts disables them while this console watches). */
export const needsRole = { 'data-operator': '' };

/**
 * A release that would move the joint further than this, degrees, asks first: below it the joint settles onto the
 * graph's command within a hair of where it is (the encoder's and the loop's own noise is far smaller).
 */
export const releaseWarnDeg = 2;

/** The pedal buttons: a jog or a setpoint moves the motor only at PEDAL_DOWN. */
export function pedalButtons(): HTMLButtonElement[] {
  return [
    button('Pedal down', () => void act(() => api('POST', '/pedal', { down: true })), { 'data-testid': 'pedal-down', ...needsRole }),
    button('Pedal up', () => void act(() => api('POST', '/pedal', { down: false })), { 'data-testid': 'pedal-up', ...needsRole }),
  ];
}

/** Jog −, stop, + and the jog speed of <m>. Stop never needs the role. */
export function jogControls(m: MotorView): HTMLElement[] {
  const speed = el('input', { type: 'number', value: '10', step: '1', min: '0', 'aria-label': `jog speed of ${m.name}`, class: 'narrow' });
  const jog = (sign: number) => act(() => api('POST', `/motors/${m.name}/jog`, { degPerS: sign * Number(speed.value) }));
  return [
    button('−', () => void jog(-1), { 'data-testid': `jog-minus-${m.name}`, ...needsRole }),
    button('stop', () => void act(() => api('POST', `/motors/${m.name}/stop`)), { 'data-testid': `jog-stop-${m.name}` }),
    button('+', () => void jog(1), { 'data-testid': `jog-plus-${m.name}`, ...needsRole }),
    speed, el('small', {}, '°/s'),
  ];
}

/** The setpoint input of <m> (within its joint limits) and its Go button. */
export function setpointControls(m: MotorView): HTMLElement[] {
  const target = el('input', { type: 'number', step: '0.1', min: String(m.minDeg), max: String(m.maxDeg), 'aria-label': `setpoint of ${m.name}`, class: 'narrow' });
  return [target, button('Go', () => void act(() => api('POST', `/motors/${m.name}/setpoint`, { deg: Number(target.value) })), { 'data-testid': `go-${m.name}`, ...needsRole })];
}

/** Home and Release of <m>. */
export function homeAndRelease(m: MotorView): HTMLButtonElement[] {
  return [
    button('Home', () => void act(() => api('POST', `/motors/${m.name}/home`)), needsRole),
    button('Release', () => void release(m.name), { 'data-testid': `release-${m.name}`, ...needsRole }),
  ];
}

/**
 * The question a release of <m> asks first, or null when it would not move the joint more than <releaseWarnDeg>:
 * releasing hands the motor back to the control loop's goal, which it reaches at its speed limit (the step cap).
 * Every number is the server's (its latest motor view).
 */
export function releaseQuestion(m: MotorView): string | null {
  const move = Math.abs(m.loopCommandDeg - m.positionDeg);
  if (!m.manual || !(move > releaseWarnDeg)) return null;
  const seconds = m.speedLimitDegS > 0 ? move / m.speedLimitDegS : Number.NaN;
  return `Release ${m.name}: it will move ${fmt(move, 1)}° back to the graph's command in about ${fmt(seconds, 1)} s. Release?`;
}

/** Releases <name> to the control loop, asking first (with the server's latest numbers) when that would move the joint. */
export async function release(name: string): Promise<boolean> {
  let motor: MotorView | undefined;
  try {
    const controllers = await api<ControllerView[]>('GET', '/controllers');
    motor = controllers.flatMap((c) => c.motors).find((m) => m.name === name);
  } catch (e) {
    show(`Release ${name}: the console could not read where the graph's command is (${(e as Error).message}); nothing released`, true);
    return false;
  }
  const question = motor ? releaseQuestion(motor) : null;
  if (question !== null && !confirm(question)) {
    show(`Release ${name} cancelled: it stays in manual`);
    return false;
  }
  return act(() => api('POST', `/motors/${name}/release`));
}

/** An editor of one persistent parameter of <m>: validated against its range, written into FRAM after confirmation. */
export function parameterEditor(m: MotorView, p: ParameterSpec): HTMLElement {
  const input = el('input', { type: 'number', step: 'any', min: String(p.min), max: String(p.max), 'data-param': p.key, 'aria-label': `${p.label} of ${m.name}`, class: 'narrow' });
  input.value = fmt(p.value, 3);
  const write = button('Write', () => {
    const value = Number(input.value);
    if (input.value.trim() === '' || !Number.isFinite(value) || value < p.min || value > p.max) {
      input.setCustomValidity(`give ${fmt(p.min, 3)}..${fmt(p.max, 3)} ${p.unit}`);
      input.reportValidity();
      return;
    }
    input.setCustomValidity('');
    if (confirm(`Write ${p.label} = ${value} ${p.unit} of ${m.name} into the module's FRAM?`)) {
      void act(() => api('PUT', `/motors/${m.name}/parameters/${p.key}`, { value })).then((ok) => { if (ok) input.dataset.dirty = ''; });
    }
  }, { 'data-testid': `write-${p.key}-${m.name}`, ...needsRole });
  input.addEventListener('input', () => { input.dataset.dirty = '1'; });
  return el('label', { title: `robot file: ${fmt(p.fileValue, 3)} ${p.unit}` }, `${p.label} `, input, ` ${p.unit} `, write);
}

/** Shows the module's parameter values in <scope>'s editors of <m>, except where the operator is typing or has not written yet. */
export function showParameters(scope: Element, m: MotorView): void {
  for (const p of m.parameters) {
    const input = scope.querySelector<HTMLInputElement>(`input[data-param="${p.key}"]`);
    if (input && !input.dataset.dirty && document.activeElement !== input) input.value = fmt(p.value, 3);
  }
}
