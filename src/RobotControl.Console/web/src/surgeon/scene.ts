import * as THREE from 'three';
import { RobotScene } from '../robot3d';
import type { WorkspaceView } from './types';

// The surgeon's 3D view: the robot (measured joints), each arm's reachable workspace drawn faintly as a point cloud,
// and a marker on each tool tip; the distance from each tip to the nearest wall sample of its arm's workspace.
const armColours = [0x2f7de1, 0x1fa37a, 0xb05cc8, 0xd08a1a];

export class SurgeonScene {
  readonly view: RobotScene;
  private walls = new Map<string, { tool: string; points: Float32Array }>();

  constructor(canvas: HTMLCanvasElement) {
    this.view = new RobotScene(canvas, { background: 0x10161d, ghost: false });
    this.view.grid.material = new THREE.LineBasicMaterial({ color: 0x2a3744 });
  }

  async load(workspace: WorkspaceView): Promise<void> {
    await this.view.load(0x9fb3c8);
    const cloud = new THREE.Group();
    workspace.arms.forEach((arm, i) => {
      const colour = armColours[i % armColours.length];
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.Float32BufferAttribute(arm.interior, 3));
      cloud.add(new THREE.Points(geometry, new THREE.PointsMaterial({ color: colour, size: 0.003, transparent: true, opacity: 0.22, depthWrite: false })));
      this.walls.set(arm.arm, { tool: arm.toolLink, points: Float32Array.from(arm.walls) });
      const tip = this.view.measured?.links[arm.toolLink];
      if (tip) {
        const marker = new THREE.Mesh(new THREE.SphereGeometry(0.0045, 20, 14), new THREE.MeshBasicMaterial({ color: 0xffd23f, depthTest: false }));
        marker.renderOrder = 10;
        const ring = new THREE.Mesh(new THREE.SphereGeometry(0.008, 20, 14), new THREE.MeshBasicMaterial({ color: colour, transparent: true, opacity: 0.45, depthTest: false }));
        ring.renderOrder = 9;
        tip.add(marker, ring);
      }
    });
    this.view.world.add(cloud);
    this.view.frame(cloud, new THREE.Vector3(0.1, 0.45, 0.62));
    const size = new THREE.Box3().setFromObject(cloud).getSize(new THREE.Vector3());
    this.view.grid.scale.setScalar((1.4 * Math.max(size.x, size.y)) / 0.4);
  }

  /** Millimetres from the arm's tool tip to the nearest wall sample of its workspace, or null. */
  wallDistanceMm(arm: string): number | null {
    const w = this.walls.get(arm);
    const tip = w ? this.view.linkPosition(w.tool) : null;
    if (!w || !tip || w.points.length === 0) return null;
    let best = Infinity;
    for (let i = 0; i < w.points.length; i += 3) {
      const dx = w.points[i] - tip.x, dy = w.points[i + 1] - tip.y, dz = w.points[i + 2] - tip.z;
      best = Math.min(best, dx * dx + dy * dy + dz * dz);
    }
    return Math.sqrt(best) * 1000;
  }
}
