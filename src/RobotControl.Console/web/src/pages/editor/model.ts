// The edited graph: what a graph file holds (robotcontrol/graph/1) plus node positions, with undo and redo.
export interface PortView { name: string; units: string; description: string }
export interface NodePorts { inputs: PortView[]; outputs: PortView[] }
export interface SettingView {
  name: string; kind: 'number' | 'integer' | 'boolean' | 'text' | 'choice'; description: string; units: string;
  minimum: number | null; maximum: number | null; required: boolean; default: unknown; choices: string[]; isFilePath: boolean;
}
export interface PluginType { name: string; description: string; assembly: string; settings: SettingView[]; ports: NodePorts | null; portsProblem: string | null }
export interface Catalog { types: PluginType[]; robot: NodePorts | null; robotFile: string | null; problems: string[] }
export interface Problem { path: string; message: string }

export interface Instance { name: string; type: string; settings: Record<string, unknown>; x: number; y: number }
export interface WireModel { from: string; to: string; delayed: boolean }
export interface GraphModel {
  robot: string | null; transport: string; loopRateHz: number; robotX: number; robotY: number;
  instances: Instance[]; wires: WireModel[];
}

export const robotInstance = 'robot';

export function emptyGraph(robot: string | null): GraphModel {
  return { robot, transport: 'virtual', loopRateHz: 1000, robotX: 1380, robotY: 20, instances: [], wires: [] };
}

/** The graph file text of the model (the server writes it again with the loader's writer when saving). */
export function toFile(g: GraphModel): Record<string, unknown> {
  const layout: Record<string, { x: number; y: number }> = {};
  const place = (name: string, x: number, y: number) => {
    if (Number.isFinite(x) && Number.isFinite(y)) layout[name] = { x: Math.round(x), y: Math.round(y) };
  };
  for (const i of g.instances) place(i.name, i.x, i.y);
  if (g.robot !== null) place(robotInstance, g.robotX, g.robotY);
  return {
    schema: 'robotcontrol/graph/1',
    ...(g.robot === null ? {} : { robot: g.robot }),
    transport: g.transport,
    loop_rate_hz: g.loopRateHz,
    instances: g.instances.map((i) => ({ name: i.name, type: i.type, settings: i.settings })),
    wires: g.wires.map((w) => (w.delayed ? { from: w.from, to: w.to, delayed: true } : { from: w.from, to: w.to })),
    layout,
  };
}

/** Reads a graph file; instances without a position keep NaN until the canvas lays them out. */
export function fromFile(file: Record<string, unknown>): GraphModel {
  const layout = (file.layout ?? {}) as Record<string, { x: number; y: number }>;
  const instances = ((file.instances ?? []) as { name: string; type: string; settings?: Record<string, unknown> }[])
    .map((i) => ({ name: i.name, type: i.type, settings: { ...(i.settings ?? {}) }, x: layout[i.name]?.x ?? NaN, y: layout[i.name]?.y ?? NaN }));
  const wires = ((file.wires ?? []) as { from: string; to: string; delayed?: boolean }[]).map((w) => ({ from: w.from, to: w.to, delayed: w.delayed === true }));
  const g: GraphModel = {
    robot: (file.robot as string | undefined) ?? null, transport: (file.transport as string | undefined) ?? 'virtual',
    loopRateHz: (file.loop_rate_hz as number | undefined) ?? 1000, robotX: layout.robot?.x ?? NaN, robotY: layout.robot?.y ?? NaN, instances, wires,
  };
  return g;
}

/** How many non-delayed wires lie between each instance and a source (its column when laid out). */
export function depths(g: GraphModel): Map<string, number> {
  const depth = new Map<string, number>(g.instances.map((i) => [i.name, 0]));
  for (let pass = 0; pass < g.instances.length; pass++) {
    for (const w of g.wires.filter((x) => !x.delayed)) {
      const from = instanceOf(w.from);
      const to = instanceOf(w.to);
      if (depth.has(from) && depth.has(to)) depth.set(to, Math.max(depth.get(to)!, depth.get(from)! + 1));
    }
  }
  return depth;
}

export function instanceOf(signal: string): string {
  return signal.startsWith(`${robotInstance}.`) ? robotInstance : signal.slice(0, signal.indexOf('.'));
}

export function portOf(signal: string): string {
  return signal.slice(instanceOf(signal).length + 1);
}

/** The wires at instance <name> (either end). */
export function wiresAt(g: GraphModel, name: string): WireModel[] {
  return g.wires.filter((w) => instanceOf(w.from) === name || instanceOf(w.to) === name);
}

/** Removes instance <name> and its wires (one change). */
export function removeInstance(g: GraphModel, name: string): void {
  g.instances = g.instances.filter((x) => x.name !== name);
  g.wires = g.wires.filter((w) => instanceOf(w.from) !== name && instanceOf(w.to) !== name);
}

/** A history as it can be kept (a draft): the graph and its undo and redo snapshots. */
export interface HistoryState { graph: GraphModel; undos: string[]; redos: string[] }

/** Undo and redo over snapshots of the model. */
export class History {
  private readonly undos: string[] = [];
  private readonly redos: string[] = [];

  constructor(public graph: GraphModel, private readonly changed: () => void) {}

  /** The graph with its undo and redo steps, to keep. */
  get state(): HistoryState { return { graph: this.graph, undos: [...this.undos], redos: [...this.redos] }; }

  /** Takes up a kept state (a draft): its graph and its undo and redo steps. */
  restore(state: HistoryState): void {
    this.graph = state.graph;
    this.undos.splice(0, this.undos.length, ...state.undos);
    this.redos.splice(0, this.redos.length, ...state.redos);
    this.changed();
  }

  /** Applies a change, remembering the graph before it. */
  change(apply: (g: GraphModel) => void): void {
    this.undos.push(JSON.stringify(this.graph));
    this.redos.length = 0;
    apply(this.graph);
    this.changed();
  }

  /** Replaces the graph (a load): a new history. */
  reset(graph: GraphModel): void {
    this.graph = graph;
    this.undos.length = 0;
    this.redos.length = 0;
    this.changed();
  }

  get canUndo(): boolean { return this.undos.length > 0; }
  get canRedo(): boolean { return this.redos.length > 0; }

  undo(): boolean { return this.step(this.undos, this.redos); }
  redo(): boolean { return this.step(this.redos, this.undos); }

  private step(from: string[], to: string[]): boolean {
    const snapshot = from.pop();
    if (snapshot === undefined) return false;
    to.push(JSON.stringify(this.graph));
    this.graph = JSON.parse(snapshot) as GraphModel;
    this.changed();
    return true;
  }
}

/** A name for a new instance of a type that no instance has yet. */
export function freshName(g: GraphModel, type: string): string {
  for (let n = 1; ; n++) {
    const name = `${type}_${n}`;
    if (!g.instances.some((i) => i.name === name)) return name;
  }
}

/** Renames an instance and the wires at it. */
export function rename(g: GraphModel, from: string, to: string): void {
  const i = g.instances.find((x) => x.name === from);
  if (!i) return;
  i.name = to;
  const move = (signal: string) => (instanceOf(signal) === from ? `${to}.${portOf(signal)}` : signal);
  for (const w of g.wires) {
    w.from = move(w.from);
    w.to = move(w.to);
  }
}

/** What a problem is about: the node (an instance's or its layout's path) or the wire it names, else null (the graph). */
export function problemTarget(g: GraphModel, p: Problem): { node: string } | { wire: number } | null {
  const instance = /^\$\.instances\[(\d+)\]/.exec(p.path);
  const wire = /^\$\.wires\[(\d+)\]/.exec(p.path);
  const layout = /^\$\.layout\.([^.]+)/.exec(p.path);
  const node = instance ? g.instances[Number(instance[1])]?.name : layout ? layout[1] : undefined;
  if (node !== undefined) return { node };
  return wire && g.wires[Number(wire[1])] ? { wire: Number(wire[1]) } : null;
}

/** The words naming a problem's node or wire (`scaling_right`, `a.out -> b.in`), or '' for the graph. */
export function targetName(g: GraphModel, target: { node: string } | { wire: number } | null): string {
  if (target === null) return '';
  if ('node' in target) return target.node;
  const w = g.wires[target.wire];
  return `${w.from} -> ${w.to}`;
}
