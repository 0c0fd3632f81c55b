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

  let robots: { measured: URDFRobot; ghost: URDFRobot } | null = null;
  let arms: RobotModel['arms'] = [];
  let names: string[] = [];

  const stream = new SignalStream((subscribed, frame: Frame) => {
    if (!robots || subscribed.join() !== names.join() || frame.t.length === 0) return;
    const latest = (signal: string) => {
      const column = frame.v[names.indexOf(signal)];
      return column ? column[column.length - 1] : undefined;
    };
    for (const arm of arms) {
      arm.positionSignals.forEach((s, j) => { const v = latest(s); if (v !== undefined) robots!.measured.setJointValue(arm.joints[j], v); });
      arm.commandSignals.forEach((s, j) => { const v = latest(s); if (v !== undefined) robots!.ghost.setJointValue(arm.joints[j], v); });
    }
  }, 60);

  // One URDF of the whole robot (both arms, placed and mirrored by the host's exporter), drawn twice: measured and ghost.
  void api<RobotModel>('GET', '/model').then((model) => {
    const loader = new URDFLoader();
    const measured = loader.parse(model.urdf);
    const ghost = loader.parse(model.urdf);
    ghost.traverse((o) => {
      const mesh = o as THREE.Mesh;
      if (mesh.isMesh) mesh.material = new THREE.MeshStandardMaterial({ color: 0xff8800, transparent: true, opacity: 0.3, depthWrite: false, side: THREE.DoubleSide });
    });
    measured.traverse((o) => {
      const mesh = o as THREE.Mesh;
      if (mesh.isMesh) mesh.material = new THREE.MeshStandardMaterial({ color: 0x5a7da8, metalness: 0.2, roughness: 0.5, side: THREE.DoubleSide });
    });
    world.add(measured, ghost);
    robots = { measured, ghost };
    arms = model.arms;
    names = arms.flatMap((a) => [...a.positionSignals, ...a.commandSignals]);
    frameCamera(measured);
    stream.subscribe(names);
  });

  // Points the orbit camera at the robot and backs off to see all of it.
  function frameCamera(robot: URDFRobot): void {
    world.updateMatrixWorld(true);
    const box = new THREE.Box3().setFromObject(robot);
    if (box.isEmpty()) return;
    const centre = box.getCenter(new THREE.Vector3());
    const size = box.getSize(new THREE.Vector3()).length();
    controls.target.copy(centre);
    camera.position.copy(centre).add(new THREE.Vector3(0.55, 0.4, 0.75).multiplyScalar(size));
    camera.near = size / 100;
    camera.far = size * 20;
    camera.updateProjectionMatrix();
    grid.position.y = box.min.y;
    controls.update();
  }

  let running = true;
  const frame = () => {
    if (!running) return;
    controls.update();
    renderer.render(scene, camera);
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
  return () => { running = false; stream.close(); controls.dispose(); renderer.dispose(); };
}
