import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import URDFLoader, { type URDFRobot } from 'urdf-loader';
import { api, type RobotModel } from '../api';
import { el } from '../dom';
import { SignalStream, type Frame } from '../stream';

// 3D view: both arms from the robot's URDF, measured joints solid, commanded joints as a translucent ghost; orbit camera.
export function view3dPage(root: HTMLElement): () => void {
  const canvas = el('canvas', { 'data-testid': 'view3d', width: '960', height: '600' });
  root.append(el('p', {}, 'Solid: measured joints. Translucent: commanded. Drag to orbit, wheel to zoom.'), canvas);
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
  renderer.setSize(960, 600, false);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf4f6f8);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 2.2));
  const light = new THREE.DirectionalLight(0xffffff, 1.5);
  light.position.set(0.3, 0.5, 0.4);
  scene.add(light);
  const grid = new THREE.GridHelper(0.4, 20, 0x99aabb, 0xccd5dd);
  grid.position.y = -0.12;
  scene.add(grid);
  const camera = new THREE.PerspectiveCamera(45, 960 / 600, 0.001, 10);
  camera.position.set(0.15, 0.11, 0.19);
  const controls = new OrbitControls(camera, canvas);
  controls.target.set(0, 0, 0.02);
  controls.update();
  // URDF is z-up; three.js is y-up.
  const world = new THREE.Group();
  world.rotation.x = -Math.PI / 2;
  scene.add(world);

  const arms: { measured: URDFRobot; ghost: URDFRobot; positions: string[]; commands: string[] }[] = [];
  let names: string[] = [];
  let jointNames: string[] = [];
  let running = true;

  const stream = new SignalStream((subscribed, frame: Frame) => {
    if (subscribed.join() !== names.join() || frame.t.length === 0) return;
    const latest = (signal: string) => {
      const column = frame.v[names.indexOf(signal)];
      return column ? column[column.length - 1] : undefined;
    };
    for (const arm of arms) {
      arm.positions.forEach((s, j) => { const v = latest(s); if (v !== undefined) arm.measured.setJointValue(jointNames[j], v); });
      arm.commands.forEach((s, j) => { const v = latest(s); if (v !== undefined) arm.ghost.setJointValue(jointNames[j], v); });
    }
  }, 60);

  void api<RobotModel>('GET', '/model').then((model) => {
    jointNames = model.joints;
    const loader = new URDFLoader();
    for (const arm of model.arms) {
      const group = new THREE.Group();
      const [x, y, z] = arm.baseOffsetM;
      const placement = new THREE.Matrix4().makeTranslation(x, y, z);
      if (arm.mirrorNormal) {
        const [nx, ny, nz] = arm.mirrorNormal;
        const l = Math.hypot(nx, ny, nz);
        const [a, b, c] = [nx / l, ny / l, nz / l];
        placement.multiply(new THREE.Matrix4().set(
          1 - 2 * a * a, -2 * a * b, -2 * a * c, 0,
          -2 * a * b, 1 - 2 * b * b, -2 * b * c, 0,
          -2 * a * c, -2 * b * c, 1 - 2 * c * c, 0,
          0, 0, 0, 1));
      }
      group.matrixAutoUpdate = false;
      group.matrix.copy(placement);
      const measured = loader.parse(model.urdf);
      const ghost = loader.parse(model.urdf);
      ghost.traverse((o) => {
        const mesh = o as THREE.Mesh;
        if (mesh.isMesh) mesh.material = new THREE.MeshStandardMaterial({ color: 0xff8800, transparent: true, opacity: 0.3, depthWrite: false, side: THREE.DoubleSide });
      });
      measured.traverse((o) => {
        const mesh = o as THREE.Mesh;
        if (mesh.isMesh) (mesh.material as THREE.Material).side = THREE.DoubleSide;
      });
      group.add(measured, ghost);
      world.add(group);
      arms.push({ measured, ghost, positions: arm.positionSignals, commands: arm.commandSignals });
    }
    names = model.arms.flatMap((a) => [...a.positionSignals, ...a.commandSignals]);
    stream.subscribe(names);
  });

  const frame = () => {
    if (!running) return;
    controls.update();
    renderer.render(scene, camera);
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
  return () => { running = false; stream.close(); controls.dispose(); renderer.dispose(); };
}
