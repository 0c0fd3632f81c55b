import { markFirstValue, onRestart } from '../api';
import { button, el, fmt } from '../dom';
import { RobotScene } from '../robot3d';
import { SignalStream, type Frame } from '../stream';

// 3D view: both arms from the robot's URDF, measured joints solid, commanded joints as a translucent ghost, each arm
// labelled; orbit camera with a reset. The view fills the page's width and most of the window's height.
export function view3dPage(root: HTMLElement): () => void {
  const canvas = el('canvas', { 'data-testid': 'view3d' });
  const stage = el('div', { class: 'v3d-stage' }, canvas);
  const readout = el('table', { class: 'kv', 'data-testid': 'joint-values' });
  const reset = button('Reset view', () => view.resetView(), { 'data-testid': 'reset-view' });
  root.append(el('div', { class: 'toolbar' }, reset, el('span', {}, 'Solid: measured joints. Translucent: commanded. Drag to orbit, wheel to zoom.')), stage, readout);
  const cells = new Map<string, HTMLElement>();
  const view = new RobotScene(canvas, { background: 0xf4f6f8, ghost: true });
  const resize = () => view.resize(stage.clientWidth, stage.clientHeight);
  const observer = new ResizeObserver(resize);
  observer.observe(stage);
  resize();
  let names: string[] = [];

  const stream = new SignalStream((subscribed, frame: Frame) => {
    if (subscribed.join() !== names.join() || frame.t.length === 0) return;
    view.setJoints((signal) => {
      const column = frame.v[names.indexOf(signal)];
      return column ? column[column.length - 1] : undefined;
    });
    names.forEach((signal, i) => {
      const column = frame.v[i];
      const cell = cells.get(signal);
      if (cell && column && column.length > 0) cell.textContent = fmt(column[column.length - 1], 6);
    });
    if (names.length > 0) markFirstValue(root);
  }, 60);

  void view.load().then(() => {
    names = view.signals;
    readout.replaceChildren(el('tr', {}, el('th', {}, 'signal'), el('th', {}, 'rad')), ...names.map((signal) => {
      const cell = el('td', { 'data-testid': `joint-${signal}` }, '');
      cells.set(signal, cell);
      return el('tr', {}, el('th', {}, signal), cell);
    }));
    stream.subscribe(names);
  });
  // A restarted server: the joint values shown were the old run's; the new stream fills them again.
  const leaveRestart = onRestart(() => { for (const cell of cells.values()) cell.textContent = ''; });
  view.start();
  return () => { leaveRestart(); observer.disconnect(); stream.close(); view.dispose(); };
}
