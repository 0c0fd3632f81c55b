import { api, act, markFirstValue, type ControllerView, type MotorView, type StatusReply } from '../api';
import { el, button, fmt } from '../dom';
import { homeAndRelease, jogControls, needsRole, parameterEditor, pedalButtons, setpointControls, showParameters } from '../motorcontrols';
import { emergencyStop } from '../statusbar';

// Bus and controllers: discover; per controller its ID, friendly name, model, firmware, status and alerts; per motor
// its live position/current/PWM, parameters (validated, written to FRAM after confirmation), jog, setpoint, home, torque.
export function busPage(root: HTMLElement): () => void {
  const toolbar = el('div', { class: 'toolbar' },
    button('Discover', () => void act(() => api('POST', '/discover')).then(refresh), { 'data-testid': 'discover', ...needsRole }),
    button('Torque on', () => void act(() => api('POST', '/torque', { on: true })), { 'data-testid': 'torque-on', ...needsRole }),
    button('Torque off', () => void act(() => api('POST', '/torque', { on: false })), { 'data-testid': 'torque-off', ...needsRole }),
    ...pedalButtons(),
    button('Home all', () => void act(() => api('POST', '/home')), { 'data-testid': 'home-all', ...needsRole }),
    button('Clear faults', () => void act(() => api('POST', '/faults/clear')), { 'data-testid': 'clear-faults', ...needsRole }),
    button('E-STOP', emergencyStop, { 'data-testid': 'estop', class: 'estop', 'aria-keyshortcuts': 'Space Escape' }),
    el('span', { class: 'level', 'data-testid': 'run-level' }));
  const list = el('div', { class: 'controllers', 'data-testid': 'controllers' });
  root.append(toolbar, list);
  let shape = '';

  async function refresh(): Promise<void> {
    const { status } = await api<StatusReply>('GET', '/status');
    const level = toolbar.querySelector('[data-testid=run-level]')!;
    const text = `run level ${status.robotState} · motors ${status.torqueOn ? 'on' : 'off'}`;
    if (level.textContent !== text) level.textContent = text;
    const controllers = await api<ControllerView[]>('GET', '/controllers');
    const key = controllers.map((c) => `${c.id}:${c.motors.map((m) => m.name).join(',')}`).join('|');
    if (key !== shape) {
      shape = key;
      list.replaceChildren(...controllers.map(controllerCard));
    }
    for (const c of controllers) {
      update(c);
    }
    if (controllers.some((c) => c.motors.length > 0)) markFirstValue(root);
  }

  const timer = setInterval(() => void refresh().catch(() => undefined), 300);
  void refresh();
  return () => clearInterval(timer);
}

function controllerCard(c: ControllerView): HTMLElement {
  const name = el('input', { value: c.name, 'aria-label': `name of module ${c.id}`, size: '18' });
  const card = el('section', { class: 'controller', 'data-controller': String(c.id) },
    el('h3', {}, `Module ${c.id} `, name,
      button('Rename', () => void act(() => api('PUT', `/controllers/${c.id}/name`, { name: name.value })), needsRole)),
    el('div', { class: 'facts' },
      el('span', { 'data-field': 'present' }), el('span', {}, `model ${c.model}`), el('span', {}, `firmware ${c.firmware}`),
      el('span', { 'data-field': 'reset' }), el('span', { 'data-field': 'watchdog' }), el('span', { 'data-field': 'alerts' }),
      button('Re-read parameters', () => void act(() => api('POST', `/controllers/${c.id}/reload`)), needsRole),
      button('Reboot module', () => {
        if (confirm(`Reboot module ${c.id}? It resumes from FRAM.`)) void act(() => api('POST', `/controllers/${c.id}/reboot`));
      }, { 'data-testid': `reboot-${c.id}`, ...needsRole })),
    el('table', { class: 'motors' },
      el('thead', {}, el('tr', {}, ...['motor', 'position °', 'current A', 'PWM', 'torque', 'errors', 'parameters', 'jog', 'setpoint', ''].map((h) => el('th', {}, h)))),
      el('tbody', {}, ...c.motors.map(motorRow))));
  return card;
}

function motorRow(m: MotorView): HTMLElement {
  return el('tr', { 'data-motor': m.name },
    el('td', {}, el('strong', {}, m.name), el('br'), el('small', {}, `ch ${m.channel}`)),
    el('td', { 'data-field': 'position', 'data-testid': `position-${m.name}` }),
    el('td', { 'data-field': 'current' }),
    el('td', { 'data-field': 'pwm' }),
    el('td', { 'data-field': 'torque' }),
    el('td', { 'data-field': 'errors' }),
    el('td', {}, el('div', { class: 'params' }, ...m.parameters.map((p) => parameterEditor(m, p)))),
    el('td', { class: 'jog' }, ...jogControls(m)),
    el('td', {}, ...setpointControls(m)),
    el('td', {}, ...homeAndRelease(m)));
}

function update(c: ControllerView): void {
  const card = document.querySelector<HTMLElement>(`[data-controller="${c.id}"]`);
  if (!card) return;
  const set = (scope: Element, field: string, text: string) => {
    const e = scope.querySelector(`[data-field="${field}"]`);
    if (e && e.textContent !== text) e.textContent = text;
  };
  // A module that stopped answering is not shown as healthy: its last values stay, said to be its last.
  const silent = !c.present || c.missedReplies > 0;
  card.classList.toggle('missing', silent);
  set(card, 'present', c.missedReplies > 0 ? `NOT ANSWERING (${c.missedReplies} polls missed): the values below are the last it gave` : c.present ? 'present' : 'MISSING');
  set(card, 'reset', `last reset: ${c.resetCause} (${c.resets} this session)`);
  set(card, 'watchdog', `watchdog ${c.watchdog}`);
  set(card, 'alerts', c.hardwareErrors.length ? `alerts: ${c.hardwareErrors.join(', ')}` : 'no alerts');
  for (const m of c.motors) {
    const row = card.querySelector(`[data-motor="${m.name}"]`);
    if (!row) continue;
    set(row, 'position', fmt(m.positionDeg, 2));
    set(row, 'current', silent ? `${fmt(m.currentA, 3)} (last)` : fmt(m.currentA, 3));
    set(row, 'pwm', String(m.pwm));
    set(row, 'torque', silent ? 'unknown: no answer' : `${m.torqueOn ? 'on' : 'off'}${m.manual ? ' · manual' : ''}`);
    set(row, 'errors', m.errors.join(', ') || '—');
    showParameters(row, m);
  }
}
