// Replies of the surgeon's view's endpoints (docs/console.md).
export interface HandView {
  arm: string; clutchSignal: string | null; lockSignal: string | null; scaling: string | null; scale: number | null;
  scaleMin: number; scaleMax: number; scaleSettable: boolean; wallSignals: string[]; wallMaxForceN: number; reachErrorSignal: string | null;
}
export interface PedalView { signal: string; drives: string }
export interface FaultView { timeSeconds: number; words: string; check: string; subject: string; arm: string; measured: number; limit: number; unit: string; action: string }
export interface SurgeonView { hands: HandView[]; pedals: PedalView[]; faults: FaultView[] }
export interface ArmWorkspaceView { arm: string; toolLink: string; interior: number[]; walls: number[] }
export interface WorkspaceView { arms: ArmWorkspaceView[] }

/** The latest streamed value of a signal, or undefined. */
export type Latest = (signal: string) => number | undefined;
