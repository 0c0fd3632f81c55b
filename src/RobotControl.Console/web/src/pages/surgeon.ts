import { api, markFirstValue, onRestart, type StatusReply } from '../api';
import { button, el } from '../dom';
import { emergencyStop, resetFaults, torqueOn } from '../statusbar';
import { SignalStream, type Frame } from '../stream';
import { faultsPanel } from '../surgeon/faults';
import { handsPanel, type HandsPanel } from '../surgeon/hands';
import { SurgeonScene } from '../surgeon/scene';
import type { SurgeonView, WorkspaceView } from '../surgeon/types';
import { videoPanel } from '../surgeon/video';

// The surgeon's view (full screen at 1920x1080, kiosk/app mode): the arms in 3D with tool tips and workspace, the
// endoscope video, the run level large with the pedals, per hand clutch, lock, scale and wall proximity, an E-STOP
// button (Space or Esc) and the faults in plain words.
const levelWords: Record<string, [string, string]> = {
  E_STOP: ['E-STOP', 'Emergency stop: the robot is stopped. Reset clears the faults; then home the arms.'],
  INIT: ['INIT', 'Motors off: Home the arms turns the motors on and homes them.'],
  HOMING: ['HOMING', 'Homing the joints from their pots.'],
  PEDAL_UP: ['PEDAL_UP', 'Holding: press the pedal to operate.'],
  PEDAL_DOWN: ['PEDAL_DOWN', 'Operating: the arms follow the hands.'],
};

export function surgeonPage(root: HTMLElement): () => void {
  const level = el('div', { class: 'level', 'data-testid': 'run-level' }, '…');
  const levelNote = el('div', { class: 'level-note', 'data-testid': 'run-level-note' });
  // Getting back from a stop without leaving the view: Reset at E-STOP, then Home the arms at INIT (each confirmed).
  const reset = button('Reset', resetFaults, { class: 'recover', 'data-testid': 'surgeon-reset', 'data-operator': '', hidden: '' });
  const home = button('Home the arms', torqueOn, { class: 'recover', 'data-testid': 'surgeon-home', 'data-operator': '', hidden: '' });
  const role = el('div', { class: 'role-note', 'data-testid': 'surgeon-role' });
  const estop = el('button', { type: 'button', class: 'estop big', 'data-testid': 'surgeon-estop', 'aria-keyshortcuts': 'Space Escape' },
    'E-STOP', el('kbd', {}, 'Space / Esc'));
  const canvas = el('canvas', { 'data-testid': 'surgeon-3d' });
  const stage = el('div', { class: 's-3d' }, canvas);
  const video = videoPanel();
  const side = el('div', { class: 's-side' }, video.element);
  const faults = faultsPanel();
  root.append(el('div', { class: 'surgeon' },
    el('div', { class: 's-top' }, el('div', { class: 's-level' }, level, reset, home, levelNote), role, estop),
    el('div', { class: 's-main' }, stage, side),
    faults.element));

  const scene = new SurgeonScene(canvas);
  let hands: HandsPanel | null = null;
  let names: string[] = [];
  let values = new Map<string, number>();
  let operator = false;
  let timer = 0;
  let lastWall = 0;
  const wallMm = new Map<string, number | null>();

  estop.addEventListener('click', emergencyStop);
  // Space and Esc: the status bar's keys, on every page.

  const stream = new SignalStream((subscribed, frame: Frame) => {
    if (subscribed.join() !== names.join() || frame.t.length === 0) return;
    const next = new Map<string, number>();
    names.forEach((n, i) => { const column = frame.v[i]; if (column && column.length > 0) next.set(n, column[column.length - 1]); });
    values = next;
    scene.view.setJoints((s) => values.get(s));
  }, 30);

  // A restarted server: the hands' values and wall distances were the old run's; the new stream fills them again.
  const leaveRestart = onRestart(() => {
    values = new Map();
    wallMm.clear();
  });

  const resize = () => scene.view.resize(stage.clientWidth, stage.clientHeight);
  const observer = new ResizeObserver(resize);
  observer.observe(stage);

  async function poll(): Promise<void> {
    try {
      const [status, surgeon] = await Promise.all([api<StatusReply>('GET', '/status'), api<SurgeonView>('GET', '/surgeon')]);
      const [word, note] = levelWords[status.status.robotState] ?? [status.status.robotState, ''];
      level.textContent = word;
      level.dataset.level = status.status.robotState;
      levelNote.textContent = note;
      markFirstValue(root);
      reset.hidden = status.status.robotState !== 'E_STOP';
      home.hidden = status.status.robotState !== 'INIT';
      operator = status.operator.you;
      role.textContent = operator ? '' : 'Watching: E-STOP works from here; take the operator role (top right) to change the scale.';
      faults.show(surgeon.faults);
      hands?.refresh(surgeon.hands);
      hands?.states(surgeon.faults, status.status.robotState);
      scene.view.markFaulted(new Set(surgeon.faults.map((f) => f.arm).filter((a) => a !== '')));
    } catch {
      level.textContent = 'NO LINK';
      level.dataset.level = 'NO_LINK';
      levelNote.textContent = 'The console server does not answer.';
    }
  }

  void Promise.all([api<SurgeonView>('GET', '/surgeon'), api<WorkspaceView>('GET', '/workspace')]).then(async ([surgeon, workspace]) => {
    hands = handsPanel(surgeon.hands, surgeon.pedals);
    side.append(hands.element);
    await scene.load(workspace);
    resize();
    const extra = [...surgeon.hands.flatMap((h) => [h.clutchSignal, h.lockSignal, h.reachErrorSignal, ...h.wallSignals]), ...surgeon.pedals.map((p) => p.signal)];
    names = [...scene.view.signals, ...extra.filter((s): s is string => s !== null)];
    stream.subscribe(names);
  });
  void poll();
  timer = window.setInterval(() => void poll(), 250);
  scene.view.start(() => {
    if (!hands) return;
    const now = performance.now();
    if (now - lastWall > 100) {
      lastWall = now;
      for (const arm of scene.view.model?.arms ?? []) wallMm.set(arm.name, scene.wallDistanceMm(arm.name));
    }
    hands.update((s) => values.get(s), (arm) => wallMm.get(arm) ?? null, operator);
  });

  return () => {
    window.clearInterval(timer);
    leaveRestart();
    observer.disconnect();
    stream.close();
    video.stop();
    scene.view.dispose();
  };
}
