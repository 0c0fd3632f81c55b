import { act, api, ApiError, onRestart } from '../api';
import { button, el, fmt } from '../dom';

interface MotorState { name: string; calibrated: boolean; verified: boolean; worstDeg: number | null; date: string | null }
interface ModuleState { id: number; name: string; commissioned: boolean; firmware: number | null; motors: MotorState[] }
interface UnitState { unit: string; file: string; date: string | null; error: string | null; modules: ModuleState[] }
interface JobState { step: string; state: string; prompt: string | null; outcome: string | null }
interface BringUpView { unit: UnitState; job: JobState | null; lines: { sequence: number; text: string }[] }

/** Controls that need the operator role (role.ts disables them while this console watches). */
const needsRole = { 'data-operator': '' };
const stepWords: Record<string, string> = { commission: 'Commission', calibrate: 'Calibrate pots' };

// Bring-up (robotctl console --bring-up): the unit's state as its unit file has it (per module: commissioned, ID,
// firmware; per motor: pot calibrated and verified, worst degrees), the two steps run on the server one at a time with
// their progress lines, the step's question (connect the next module, the arm in its fixture pose) with Continue, and
// STOP for every console. A failed or stopped step's line (naming the module or motor and what to do) is shown in
// full width until the next step starts.
export function bringupPage(root: HTMLElement): () => void {
  const poll = el('input', { type: 'checkbox', 'data-testid': 'bringup-poll' });
  const module = el('select', { 'data-testid': 'bringup-module', 'aria-label': 'module to calibrate' }, el('option', { value: '' }, 'every module'));
  const redo = el('input', { type: 'checkbox', 'data-testid': 'bringup-redo' });
  const start = (path: string, body: unknown) => void act(async () => {
    const reply = await api<{ message: string }>('POST', path, body);
    await refresh();
    return reply;
  });
  const commission = button('Commission', () => start('/bringup/commission', { poll: poll.checked }), { 'data-testid': 'bringup-commission', ...needsRole });
  const calibrate = button('Calibrate pots', () => start('/bringup/calibrate', { module: module.value === '' ? null : Number(module.value), redo: redo.checked }), { 'data-testid': 'bringup-calibrate', ...needsRole });
  const stop = button('STOP', () => void act(async () => {
    const reply = await api<{ message: string }>('POST', '/bringup/stop');
    await refresh();
    return reply;
  }), { 'data-testid': 'bringup-stop', class: 'estop' });
  const toolbar = el('div', { class: 'toolbar' },
    commission, el('label', {}, poll, ' wait for each module by itself'), ' · ',
    calibrate, module, el('label', {}, redo, ' again (calibrated ones too)'), ' · ', stop,
    el('span', { class: 'bringup-state', 'data-testid': 'bringup-state' }));
  const prompt = el('div', { class: 'bringup-prompt', 'data-testid': 'bringup-prompt', role: 'status', hidden: '' });
  const promptText = el('span', { 'data-testid': 'bringup-prompt-text' });
  prompt.append(promptText, button('Continue', () => start('/bringup/continue', undefined), { 'data-testid': 'bringup-continue', ...needsRole }));
  const result = el('div', { class: 'bringup-result', 'data-testid': 'bringup-result', hidden: '' });
  const unitLine = el('p', { 'data-testid': 'bringup-unit' });
  const table = el('table', { class: 'motors', 'data-testid': 'bringup-table' });
  const log = el('ol', { class: 'bringup-log', 'data-testid': 'bringup-log' });
  root.append(toolbar, prompt, result, unitLine, table, el('h3', {}, 'Progress'), log);
  let after = 0;
  let shape = '';
  // A restarted server numbers its lines from 1 again: the old run's go and the log is read again from the start; an
  // answer asked for before the restart is dropped (run counts the restarts), as on the run-status page.
  let run = 0;
  const leaveRestart = onRestart(() => {
    run += 1;
    after = 0;
    log.replaceChildren();
  });

  function showUnit(u: UnitState): void {
    unitLine.textContent = u.error ?? `unit ${u.unit} (${u.file})${u.date ? `, last written ${u.date}` : ', not commissioned yet'}`;
    unitLine.className = u.error ? 'error' : '';
    const key = u.modules.map((m) => m.id).join(',');
    if (key !== shape) {
      shape = key;
      module.replaceChildren(el('option', { value: '' }, 'every module'), ...u.modules.map((m) => el('option', { value: String(m.id) }, `module ${m.id} (${m.name})`)));
    }
    table.replaceChildren(el('tr', {}, ...['module', 'ID', 'commissioned', 'firmware', 'motor', 'pot'].map((h) => el('th', {}, h))),
      ...u.modules.flatMap((m) => m.motors.map((motor, i) => el('tr', { 'data-testid': `bringup-motor-${motor.name}` },
        ...(i === 0 ? [
          el('td', { rowspan: String(m.motors.length) }, m.name),
          el('td', { rowspan: String(m.motors.length) }, String(m.id)),
          el('td', { rowspan: String(m.motors.length), 'data-testid': `bringup-module-${m.id}` }, m.commissioned ? 'commissioned' : 'not commissioned'),
          el('td', { rowspan: String(m.motors.length) }, m.firmware === null ? '—' : String(m.firmware)),
        ] : []),
        el('td', {}, motor.name),
        el('td', { 'data-testid': `bringup-pot-${motor.name}` }, potWords(motor))))));
  }

  function showJob(job: JobState | null): void {
    const state = toolbar.querySelector('[data-testid=bringup-state]')!;
    state.textContent = job === null ? 'no step run yet' : `${stepWords[job.step] ?? job.step}: ${job.state}`;
    prompt.hidden = job?.prompt == null;
    promptText.textContent = job?.prompt ?? '';
    const failed = job !== null && (job.state === 'failed' || job.state === 'stopped');
    result.hidden = job?.outcome == null;
    result.textContent = job?.outcome ?? '';
    result.className = `bringup-result ${failed ? 'error' : 'ok'}`;
    result.setAttribute('role', failed ? 'alert' : 'status');
  }

  async function refresh(): Promise<void> {
    const asked = run;
    const view = await api<BringUpView>('GET', `/bringup?after=${after}`);
    if (asked !== run) return;
    showUnit(view.unit);
    showJob(view.job);
    for (const line of view.lines) {
      if (line.sequence <= after) continue; // a poll and an action's refresh crossed: each line once
      after = line.sequence;
      log.append(el('li', { class: line.text.startsWith('== ') ? 'step' : '' }, line.text));
    }
    if (view.lines.length > 0) log.lastElementChild?.scrollIntoView({ block: 'nearest' });
  }

  const tick = () => void refresh().catch((e: ApiError) => {
    unitLine.textContent = e.status === 404 ? 'this console serves a running robot: bring a unit up with robotctl console --bring-up <robot-file> --transport serial:<port> --unit <name>' : e.message;
    unitLine.className = 'error';
  });
  tick();
  const timer = setInterval(tick, 300);
  return () => { clearInterval(timer); leaveRestart(); };
}

/** A motor's pot calibration in words. */
function potWords(m: MotorState): string {
  if (!m.calibrated) return 'not calibrated';
  const worst = m.worstDeg === null ? '' : `, worst ${fmt(m.worstDeg, 2)} deg`;
  return m.verified ? `calibrated and verified${worst}` : `calibrated, not verified${worst}: calibrate it again`;
}
