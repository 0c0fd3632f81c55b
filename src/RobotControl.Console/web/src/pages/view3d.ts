import { el } from '../dom';
import { RobotScene } from '../robot3d';
import { SignalStream, type Frame } from '../stream';

// 3D view: both arms from the robot's URDF, measured joints solid, commanded joints as a translucent ghost; orbit camera.
export function view3dPage(root: HTMLElement): () => void {
  const canvas = el('canvas', { 'data-testid': 'view3d', width: '960', height: '600' });
  root.append(el('p', {}, 'Solid: measured joints. Translucent: commanded. Drag to orbit, wheel to zoom.'), canvas);
  const view = new RobotScene(canvas, { background: 0xf4f6f8, ghost: true });
  view.resize(960, 600);
  let names: string[] = [];

  const stream = new SignalStream((subscribed, frame: Frame) => {
    if (subscribed.join() !== names.join() || frame.t.length === 0) return;
    view.setJoints((signal) => {
      const column = frame.v[names.indexOf(signal)];
      return column ? column[column.length - 1] : undefined;
    });
  }, 60);

  void view.load().then(() => {
    names = view.signals;
    stream.subscribe(names);
  });
  view.start();
  return () => { stream.close(); view.dispose(); };
}
