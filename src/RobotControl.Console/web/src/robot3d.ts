import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import URDFLoader, { type URDFRobot } from 'urdf-loader';
import { api, type RobotModel } from './api';

// The robot in 3D, shared by the 3D view and the surgeon's view: one URDF of the whole robot (both arms, placed and
// mirrored by the host's exporter) drawn with measured joints, optionally again as a translucent ghost of the
// commanded joints; orbit camera framed on it. URDF is z-up; three.js is y-up: everything robot-side sits in `world`.
export interface RobotSceneOptions {
  background: number;
  ghost: boolean;
}

export class RobotScene {
  readonly renderer: THREE.WebGLRenderer;
  readonly scene = new THREE.Scene();
  readonly camera = new THREE.PerspectiveCamera(45, 16 / 10, 0.001, 10);
  readonly controls: OrbitControls;
  readonly world = new THREE.Group();
  readonly grid = new THREE.GridHelper(0.4, 20, 0x99aabb, 0xccd5dd);
  measured: URDFRobot | null = null;
  ghost: URDFRobot | null = null;
  model: RobotModel | null = null;
  private running = true;

  constructor(readonly canvas: HTMLCanvasElement, private readonly options: RobotSceneOptions) {
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    this.scene.background = new THREE.Color(options.background);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 2.2));
    const light = new THREE.DirectionalLight(0xffffff, 1.5);
    light.position.set(0.3, 0.5, 0.4);
    this.scene.add(light);
    this.grid.position.y = -0.12;
    this.scene.add(this.grid);
    this.camera.position.set(0.15, 0.11, 0.19);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.target.set(0, 0, 0.02);
    this.controls.update();
    this.world.rotation.x = -Math.PI / 2;
    this.scene.add(this.world);
  }

  /** The ring signals to stream: measured joints, and commanded ones when a ghost is drawn. */
  get signals(): string[] {
    return (this.model?.arms ?? []).flatMap((a) => [...a.positionSignals, ...(this.options.ghost ? a.commandSignals : [])]);
  }

  /** Fetches the model, builds the robot (and its ghost) and frames the camera on it. */
  async load(color = 0x5a7da8): Promise<RobotModel> {
    const model = await api<RobotModel>('GET', '/model');
    const loader = new URDFLoader();
    this.measured = loader.parse(model.urdf);
    paint(this.measured, new THREE.MeshStandardMaterial({ color, metalness: 0.2, roughness: 0.5, side: THREE.DoubleSide }));
    this.world.add(this.measured);
    if (this.options.ghost) {
      this.ghost = loader.parse(model.urdf);
      paint(this.ghost, new THREE.MeshStandardMaterial({ color: 0xff8800, transparent: true, opacity: 0.3, depthWrite: false, side: THREE.DoubleSide }));
      this.world.add(this.ghost);
    }
    this.model = model;
    this.frame(this.measured);
    return model;
  }

  /** Sets the joints from the latest streamed values (`latest` gives undefined for a signal not in the frame). */
  setJoints(latest: (signal: string) => number | undefined): void {
    for (const arm of this.model?.arms ?? []) {
      arm.positionSignals.forEach((s, j) => { const v = latest(s); if (v !== undefined) this.measured?.setJointValue(arm.joints[j], v); });
      if (this.ghost) arm.commandSignals.forEach((s, j) => { const v = latest(s); if (v !== undefined) this.ghost!.setJointValue(arm.joints[j], v); });
    }
  }

  /** Where a link of the measured robot is, in the URDF's body frame (metres). */
  linkPosition(link: string): THREE.Vector3 | null {
    const object = this.measured?.links[link];
    if (!object) return null;
    this.world.updateMatrixWorld(true);
    const p = object.getWorldPosition(new THREE.Vector3());
    return this.world.worldToLocal(p);
  }

  /** Points the orbit camera at `object` and backs off to see all of it. */
  frame(object: THREE.Object3D, direction = new THREE.Vector3(0.55, 0.4, 0.75)): void {
    this.world.updateMatrixWorld(true);
    const box = new THREE.Box3().setFromObject(object);
    if (box.isEmpty()) return;
    const centre = box.getCenter(new THREE.Vector3());
    const size = box.getSize(new THREE.Vector3()).length();
    this.controls.target.copy(centre);
    this.camera.position.copy(centre).add(direction.clone().multiplyScalar(size));
    this.camera.near = size / 100;
    this.camera.far = size * 20;
    this.camera.updateProjectionMatrix();
    this.grid.position.y = box.min.y;
    this.controls.update();
  }

  /** Renders at `width` x `height` CSS pixels. */
  resize(width: number, height: number): void {
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / Math.max(1, height);
    this.camera.updateProjectionMatrix();
  }

  /** Renders every animation frame, calling `before` first, until disposed. */
  start(before?: () => void): void {
    const step = () => {
      if (!this.running) return;
      before?.();
      this.controls.update();
      this.renderer.render(this.scene, this.camera);
      requestAnimationFrame(step);
    };
    requestAnimationFrame(step);
  }

  dispose(): void {
    this.running = false;
    this.controls.dispose();
    this.renderer.dispose();
  }
}

function paint(robot: URDFRobot, material: THREE.Material): void {
  robot.traverse((o) => {
    const mesh = o as THREE.Mesh;
    if (mesh.isMesh) mesh.material = material;
  });
}
