import { act, api, ApiError, onReach, onRestart, show, type SessionStatus, type StatusReply } from './api';
import { button, el } from './dom';
import { watchRole, type RoleState } from './role';
import type { SurgeonView } from './surgeon/types';

// The status bar, fixed at the top of every page (docs/console.md, "Status bar"): the run level as a word in its
// colour, motors on/off as read back, faults in plain words, the operator role's state, reset and torque-on (each
// confirmed), and an E-STOP button that is never disabled. Space and Esc press E-STOP from every page (Space not while
// typing in a text field; Esc always). Its status poll is the operator role's heartbeat. When the server cannot be
// reached the bar says so at once, in full width, and names the hardware E-STOP.

/** The run levels as the server names them, with the word the bar shows. Their colours are in style.css (--level-*). */
export const levelWords: Record<string, string> = {
  E_STOP: 'E-STOP', INIT: 'INIT (motors off)', HOMING: 'HOMING', PEDAL_UP: 'PEDAL UP (holding)', PEDAL_DOWN: 'PEDAL DOWN (moving)', NO_LINK: 'NO LINK',
};

const pollMs = 500;

/** POST /api/estop: answered for every console, with or without the operator role. */
export function emergencyStop(): void {
  void act(() => api<{ message: string }>('POST', '/estop'));
}

/** True when the key goes into a text field (Space types there; Esc still stops). */
function typing(target: EventTarget | null): boolean {
  if (target instanceof HTMLTextAreaElement || target instanceof HTMLSelectElement) return true;
  if (target instanceof HTMLInputElement) return !['button', 'checkbox', 'radio', 'range', 'submit', 'reset', 'color', 'file', 'image'].includes(target.type);
  return target instanceof HTMLElement && target.isContentEditable;
}

function onKey(e: KeyboardEvent): void {
  const escape = e.key === 'Escape';
  const space = e.code === 'Space' || e.key === ' ';
  if (!(escape || (space && !typing(e.target)))) return;
  e.preventDefault();
  e.stopPropagation();
  if (!e.repeat) emergencyStop();
}

/** "ModuleMissing" -> "module missing". */
function words(name: string): string {
  return name.replace(/([a-z])([A-Z])/g, '$1 $2').toLowerCase();
}

/**
 * The faults in plain words, newest trip first: the supervisor's trips as the surgeon's view words them, then the robot
 * layer's fault flags in words. Where no trip is worded (a replay), the status's own lines stand.
 */
export function faultWords(status: SessionStatus, surgeon: SurgeonView): string[] {
  if (surgeon.faults.length === 0 && status.faults.some((f) => f.startsWith('trip:'))) return status.faults;
  return [...surgeon.faults.slice().reverse().map((f) => f.words), ...status.faults.filter((f) => !f.startsWith('trip:')).map(words)];
}

/** Reset, after a confirmation: the latched faults cleared (the operator's; the bar and the surgeon's view). */
export function resetFaults(): void {
  if (confirm('Reset: clear the latched faults. After an E-STOP the motors stay off and the arms must be homed (torque on). Reset now?')) {
    void act(() => api('POST', '/faults/clear'));
  }
}

/** Torque on, after a confirmation: the motors driven, the arms homed first when their positions are in doubt. */
export function torqueOn(): void {
  if (confirm('Torque on: drive the motors (the arms home first if their positions are in doubt). Turn torque on now?')) {
    void act(() => api('POST', '/torque', { on: true }));
  }
}

export function statusBar(bar: HTMLElement, unreachable: HTMLElement): void {
  const level = el('span', { class: 'bar-level', 'data-testid': 'bar-level', 'data-level': 'NO_LINK' }, '…');
  const motors = el('span', { class: 'bar-motors', 'data-testid': 'bar-motors' }, 'motors …');
  const faults = el('span', { class: 'bar-faults', 'data-testid': 'bar-faults' });
  const role = el('span', { id: 'role', 'data-testid': 'bar-role' });
  const claim = button('Take operator role', () => void act(async () => {
    await api('POST', '/operator');
    await poll();
    return { message: 'this console is the operator' };
  }), { id: 'claim' });
  const reset = button('Reset', resetFaults, { 'data-testid': 'bar-reset', 'data-operator': '' });
  const torque = button('Torque on', torqueOn, { 'data-testid': 'bar-torque-on', 'data-operator': '' });
  const estop = button('E-STOP', emergencyStop, { class: 'estop bar-estop', 'data-testid': 'bar-estop', 'aria-keyshortcuts': 'Space Escape', title: 'E-STOP (Space or Esc, from every page)' });
  estop.append(el('kbd', {}, 'Space / Esc'));
  bar.append(level, motors, faults, el('span', { class: 'bar-role' }, role, claim), reset, torque, estop);
  const roleState = watchRole(document.getElementById('page')!);

  let down = false;
  let held: RoleState = 'watching'; // as last read: after a restart, the role this console had before it
  onRestart(() => void retake(held === 'operator'));
  onReach((yes) => {
    if (yes === !down) return;
    down = !yes;
    unreachable.hidden = yes;
    document.body.classList.toggle('unreachable', down);
    if (down) {
      level.textContent = levelWords.NO_LINK;
      level.dataset.level = 'NO_LINK';
      motors.textContent = 'motors unknown';
      delete motors.dataset.on;
      faults.textContent = 'faults unknown';
    } else {
      show('the console server answers again');
    }
  });

  /**
   * After a restart: the old run's messages go, the banner says once what starts again, and the operator role is taken
   * again if this console held it (or the banner says who has it: never silently watching).
   */
  async function retake(wasOperator: boolean): Promise<void> {
    const restarted = 'the console server restarted: plots and the event log start again';
    if (!wasOperator) {
      show(restarted);
      return;
    }
    try {
      await api('POST', '/operator');
      show(`${restarted}; this console is the operator again`);
    } catch (e) {
      const taken = e instanceof ApiError && e.status === 409;
      show(`${restarted}; ${taken ? 'another console took the operator role first: this one watches' : `the operator role was not taken again (${(e as Error).message})`}`, true);
    }
    await poll().catch(() => undefined);
  }

  async function poll(): Promise<void> {
    const [reply, surgeon] = await Promise.all([api<StatusReply>('GET', '/status'), api<SurgeonView>('GET', '/surgeon')]);
    const s = reply.status;
    document.getElementById('robot')!.textContent = `${s.robot} · ${s.transport}`;
    level.textContent = levelWords[s.robotState] ?? s.robotState;
    level.dataset.level = s.robotState;
    motors.textContent = s.torqueOn ? 'motors on' : 'motors off';
    motors.dataset.on = String(s.torqueOn);
    const plain = faultWords(s, surgeon).slice(0, 3);
    faults.textContent = plain.length === 0 ? 'no faults' : plain.join(' · ');
    faults.classList.toggle('active', plain.length > 0);
    const state: RoleState = reply.operator.you ? 'operator' : reply.operator.held ? 'held' : 'watching';
    role.textContent = { operator: 'operator', held: 'watching: held by another console', watching: 'watching' }[state];
    role.dataset.role = state;
    claim.hidden = state === 'operator';
    held = state;
    roleState(state);
  }

  window.addEventListener('keydown', onKey, { capture: true });
  const tick = () => void poll().catch((e: Error) => { if (!down) show(e.message, true); });
  tick();
  setInterval(tick, pollMs);
}
