import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { CSS2DObject, CSS2DRenderer } from 'three/addons/renderers/CSS2DRenderer.js';
import URDFLoader, { type URDFRobot } from 'urdf-loader';
import { api, type RobotModel } from './api';
import { el } from './dom';

// The robot in 3D, shared by the 3D view and the surgeon's view: one URDF of the whole robot (both arms, placed and
// mirrored by the host's exporter) drawn with measured joints, optionally again as a translucent ghost of the
// commanded joints; orbit camera framed on it, with a reset to that framing; each arm labelled by name at its base,
// and drawn red (label too) while it has a fault. URDF is z-up; three.js is y-up: everything robot-side sits in `world`.
// The canvas's parent must be positioned (the labels are laid over it).
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
  private readonly labels = new CSS2DRenderer();
  private readonly armLabels = new Map<string, HTMLElement>();
  private readonly faultMaterial = new THREE.MeshStandardMaterial({ color: 0xd93a32, metalness: 0.1, roughness: 0.6, side: THREE.DoubleSide });
  private framing: { target: THREE.Vector3; position: THREE.Vector3 } | null = null;
  private faulted = '';

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
    Object.assign(this.labels.domElement.style, { position: 'absolute', inset: '0', pointerEvents: 'none' });
    canvas.after(this.labels.domElement);
    this.controls.addEventListener('change', () => this.tellCamera());
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
    for (const arm of model.arms) {
      const base = this.measured.links[`${arm.name}_base`];
      if (!base) continue;
      const label = el('div', { class: 'arm-label', 'data-testid': `arm-label-${arm.name}` }, `${arm.name} arm`);
      base.add(new CSS2DObject(label));
      this.armLabels.set(arm.name, label);
    }
    this.frame(this.measured);
    return model;
  }

  /** Draws the arms in `arms` red (their labels too) and the others in their own colour. */
  markFaulted(arms: Set<string>): void {
    const key = [...arms].sort().join();
    if (key === this.faulted || !this.measured) return;
    this.faulted = key;
    this.canvas.dataset.faulted = key;
    this.measured.traverse((o) => {
      const mesh = o as THREE.Mesh & { userData: { own?: THREE.Material } };
      if (!mesh.isMesh) return;
      mesh.userData.own ??= mesh.material as THREE.Material;
      const arm = this.armOf(mesh);
      mesh.material = arm !== null && arms.has(arm) ? this.faultMaterial : mesh.userData.own;
    });
    for (const [arm, label] of this.armLabels) label.classList.toggle('faulted', arms.has(arm));
  }

  /** The arm a mesh of the robot belongs to (its nearest link named `<arm>_...`, as the exporter names them), or null (the body). */
  private armOf(o: THREE.Object3D): string | null {
    for (let p: THREE.Object3D | null = o; p; p = p.parent) {
      const link = p as THREE.Object3D & { isURDFLink?: boolean };
      const arm = link.isURDFLink ? this.model?.arms.find((a) => link.name.startsWith(`${a.name}_`)) : undefined;
      if (arm) return arm.name;
    }
    return null;
  }

  /** Back to the framing the view opened with (the last `frame`): the same camera and target, wherever the arms are now. */
  resetView(): void {
    if (!this.framing) return;
    this.controls.target.copy(this.framing.target);
    this.camera.position.copy(this.framing.position);
    this.controls.update();
    this.tellCamera();
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
    this.framing = { target: this.controls.target.clone(), position: this.camera.position.clone() };
    this.tellCamera();
  }

  /** The camera's position on the canvas (`data-camera`, millimetres): what a test of the view reads. */
  private tellCamera(): void {
    this.canvas.dataset.camera = this.camera.position.toArray().map((v) => Math.round(v * 1000)).join(',');
  }

  /** Renders at `width` x `height` CSS pixels. */
  resize(width: number, height: number): void {
    this.renderer.setSize(width, height, false);
    this.labels.setSize(width, height);
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
      this.labels.render(this.scene, this.camera);
      requestAnimationFrame(step);
    };
    requestAnimationFrame(step);
  }

  dispose(): void {
    this.running = false;
    this.controls.dispose();
    this.renderer.dispose();
    this.labels.domElement.remove();
  }
}

function paint(robot: URDFRobot, material: THREE.Material): void {
  robot.traverse((o) => {
    const mesh = o as THREE.Mesh;
    if (mesh.isMesh) mesh.material = material;
  });
}
