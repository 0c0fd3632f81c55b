// The node canvas: drawflow draws the model's nodes and wires and reports what the user drags; the model (History)
// stays the one source of truth and every change re-renders from it.
import Drawflow, { type ConnectionEvent } from 'drawflow';
import 'drawflow/dist/drawflow.min.css';
import { type GraphModel, type History, type NodePorts, type Problem, depths, instanceOf, portOf, problemTarget, robotInstance } from './model';

export type Selection = { node: string } | { wire: number } | null;

/**
 * The smallest text the canvas draws, on screen (px). Zoomed out so far that a node's labels would be smaller, the
 * canvas turns compact: each node shows only its name, at titlePx on screen whatever the zoom, and hides its port
 * labels, live values and problems (a port's tooltip and the problems panel still tell them); zooming in shows them
 * again. Neither Fit nor the wheel zooms out further than each node's name fits its node at titlePx.
 */
export const readablePx = 11;
const titlePx = 12;
const zoomMin = 0.3; // drawflow's floor when names would fit at any zoom

const esc = (s: string) => s.replace(/[&<>"']/g, (c) => `&#${c.charCodeAt(0)};`);

export class GraphCanvas {
  private readonly df: Drawflow;
  private readonly ids = new Map<string, number>();
  private readonly names = new Map<number, string>();
  private rendering = false;
  private picked: Selection = null;
  private fullZoom = 1; // from this zoom up, every label of a node is at least readablePx on screen
  private floorZoom = zoomMin; // the smallest zoom at which every node's name fits its node at titlePx

  constructor(
    private readonly container: HTMLElement,
    private readonly history: History,
    private readonly portsOf: (instance: string) => NodePorts | null,
    private readonly onSelect: (s: Selection) => void,
  ) {
    this.df = new Drawflow(container);
    // Deleting goes through the model (one undo step for a node and its wires): drawflow's own Delete key and
    // context-menu cross are switched off before it binds them.
    const df = this.df as unknown as { key: (e: KeyboardEvent) => void; contextmenu: (e: MouseEvent) => void };
    df.key = () => undefined;
    df.contextmenu = (e) => e.preventDefault();
    this.df.reroute = false;
    this.df.zoom_min = zoomMin;
    this.df.start();
    this.df.precanvas.style.transformOrigin = '0 0';
    // drawflow announces a wheel or button zoom before it applies it: kept at or above the readable floor.
    this.df.on('zoom', () => {
      this.df.zoom = Math.max(this.df.zoom, this.floorZoom);
      this.showZoom();
    });
    this.df.on('connectionCreated', (e) => this.connected(e));
    this.df.on('nodeMoved', (id) => this.moved(id));
    this.df.on('nodeSelected', (id) => this.select({ node: this.names.get(Number(id)) ?? '' }));
    this.df.on('connectionSelected', (e) => this.select({ wire: this.wireIndex(e) }));
    this.df.on('nodeUnselected', () => this.select(null));
    this.df.on('connectionUnselected', () => this.select(null));
  }

  get graph(): GraphModel { return this.history.graph; }

  /** Draws the whole model again (after any change; cheap for graphs of tens of nodes). */
  render(): void {
    this.rendering = true;
    try {
      this.df.clear();
      this.ids.clear();
      this.names.clear();
      const g = this.graph;
      if (g.robot !== null) this.addNode(robotInstance, 'robot', g.robotX, g.robotY);
      for (const i of g.instances) this.addNode(i.name, i.type, i.x, i.y);
      this.measureReadability();
      for (const w of g.wires) {
        const at = this.endsOf(w.from, w.to);
        if (at) this.df.addConnection(at.out, at.in, at.outClass, at.inClass);
      }
      for (const id of this.ids.values()) this.df.updateConnectionNodes(`node-${id}`);
      this.addHitPaths();
      this.markPicked();
    } finally {
      this.rendering = false;
    }
  }

  /** Renders once no wire or node is being dragged (a render mid-drag would drop it). */
  renderWhenIdle(then: () => void): void {
    const df = this.df as unknown as { connection: boolean; drag: boolean };
    if (df.connection || df.drag) {
      setTimeout(() => this.renderWhenIdle(then), 50);
      return;
    }
    this.render();
    then();
  }

  /** The SVG of wire <paramref name="index"/>, if drawn. */
  wireElement(index: number): SVGElement | null {
    const w = this.graph.wires[index];
    const at = w && this.endsOf(w.from, w.to);
    return at ? this.container.querySelector<SVGElement>(`.connection.node_in_node-${at.in}.node_out_node-${at.out}.${at.outClass}.${at.inClass}`) : null;
  }

  nodeElement(name: string): HTMLElement | null {
    const id = this.ids.get(name);
    return id === undefined ? null : this.container.querySelector<HTMLElement>(`#node-${id}`);
  }

  /** Marks delayed wires, and puts each problem on its node or wire; returns the problems that concern neither. */
  decorate(problems: Problem[]): Problem[] {
    const g = this.graph;
    this.container.querySelectorAll('.gn-bad').forEach((e) => e.classList.remove('gn-bad'));
    this.container.querySelectorAll('.gn-problems').forEach((e) => e.replaceChildren());
    g.wires.forEach((w, i) => {
      const svg = this.wireElement(i);
      if (!svg) return;
      svg.classList.toggle('delayed', w.delayed);
      svg.classList.remove('problem');
      svg.removeAttribute('data-problem');
      svg.dataset.wire = `${w.from} -> ${w.to}`;
    });
    const rest: Problem[] = [];
    for (const p of problems) {
      const text = `${p.path}: ${p.message}`;
      const target = problemTarget(g, p);
      const nodeEl = target && 'node' in target ? this.nodeElement(target.node) : null;
      if (nodeEl) {
        nodeEl.classList.add('gn-bad');
        nodeEl.querySelector('.gn-problems')!.append(Object.assign(document.createElement('div'), { textContent: text }));
        continue;
      }
      const svg = target && 'wire' in target ? this.wireElement(target.wire) : null;
      if (target && 'wire' in target && svg) {
        svg.classList.add('problem');
        svg.dataset.problem = [svg.dataset.problem, text].filter(Boolean).join('\n');
        const w = g.wires[target.wire];
        const port = this.container.querySelector(`.gn-port[data-signal="${CSS.escape(w.to)}"]`);
        port?.classList.add('gn-bad');
        port?.setAttribute('title', text);
      }
      rest.push(p);
    }
    return rest;
  }

  /** Shows live values: each output with its own, each input with its source's. */
  showLive(values: Map<string, number> | null): void {
    const sources = new Map(this.graph.wires.map((w) => [w.to, w.from]));
    this.container.querySelectorAll<HTMLElement>('.gn-port').forEach((row) => {
      const signal = row.dataset.signal!;
      const v = values?.get(row.dataset.dir === 'out' ? signal : sources.get(signal) ?? '');
      row.querySelector('.gn-live')!.textContent = v === undefined ? '' : formatValue(v);
    });
  }

  /**
   * Places the nodes that have no position (a graph file without layout): columns by distance from a source, each
   * as wide as its widest node, the robot last; measured on the drawn nodes. Returns true when it moved any.
   */
  layOut(): boolean {
    const g = this.graph;
    const missing = g.instances.filter((i) => !Number.isFinite(i.x) || !Number.isFinite(i.y));
    const robotMissing = g.robot !== null && (!Number.isFinite(g.robotX) || !Number.isFinite(g.robotY));
    if (missing.length === 0 && !robotMissing) return false;
    const depth = depths(g);
    this.container.classList.add('sizing'); // measure with room for live values
    const sizes = new Map([...this.ids.keys()].map((name) => [name, { w: this.nodeElement(name)?.offsetWidth ?? 200, h: this.nodeElement(name)?.offsetHeight ?? 100 }]));
    this.container.classList.remove('sizing');
    const size = (name: string) => sizes.get(name)!;
    const columns = Math.max(0, ...depth.values()) + 1;
    const width = Array.from({ length: columns }, (_, c) => Math.max(0, ...g.instances.filter((i) => depth.get(i.name) === c).map((i) => size(i.name).w)));
    const left = width.reduce<number[]>((xs, w, c) => [...xs, xs[c] + w + 70], [40]);
    const top = new Array<number>(columns).fill(40);
    for (const i of g.instances) {
      const c = depth.get(i.name)!;
      if (missing.includes(i)) {
        i.x = left[c];
        i.y = top[c];
      }
      top[c] = Math.max(top[c], i.y + size(i.name).h + 40);
    }
    if (robotMissing) {
      g.robotX = left[columns];
      g.robotY = 40;
    }
    return true;
  }

  /**
   * The top of a free spot for a node at canvas x (about a node wide): below every drawn node that overlaps that
   * column, with the layout's gap, and never above `top`; a tall node (an IK with a port per joint
   * and its measured joints) does not hide the one placed after it.
   */
  freeTop(x: number, top: number, width = 300): number {
    let y = top;
    for (const name of this.ids.keys()) {
      const e = this.nodeElement(name);
      if (e && e.offsetLeft < x + width && e.offsetLeft + e.offsetWidth > x) y = Math.max(y, e.offsetTop + e.offsetHeight + 40);
    }
    return y;
  }

  /**
   * Moves nodes down until none covers another: a node drawn again with the ports its settings give it (a Touch
   * with a script, an IK with the robot's joints) can grow over one placed below it while it was smaller. Nodes
   * keep their order from the top; the model's positions follow (no undo step: nothing the user did). True when
   * one moved.
   */
  separate(): boolean {
    const gap = 40;
    const boxes = [...this.ids.keys()].flatMap((name) => {
      const e = this.nodeElement(name);
      return e ? [{ name, x: e.offsetLeft, y: e.offsetTop, w: e.offsetWidth, h: e.offsetHeight, moved: false }] : [];
    }).sort((a, b) => a.y - b.y || a.x - b.x);
    const placed: typeof boxes = [];
    for (const b of boxes) {
      for (let again = true; again;) {
        again = false;
        for (const a of placed) {
          if (a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h) {
            b.y = a.y + a.h + gap;
            b.moved = true;
            again = true;
          }
        }
      }
      placed.push(b);
    }
    const g = this.graph;
    for (const b of boxes.filter((x) => x.moved)) {
      if (b.name === robotInstance) g.robotY = b.y;
      const i = g.instances.find((x) => x.name === b.name);
      if (i) i.y = b.y;
    }
    return boxes.some((b) => b.moved);
  }

  /** Scales and moves the view so every node shows, or as many as the readable floor lets (then drag to scroll). */
  fit(): void {
    const nodes = [...this.container.querySelectorAll<HTMLElement>('.drawflow-node')];
    if (nodes.length === 0) return;
    this.container.classList.add('sizing'); // as wide as they are with live values
    const minX = Math.min(...nodes.map((n) => n.offsetLeft));
    const minY = Math.min(...nodes.map((n) => n.offsetTop));
    const maxX = Math.max(...nodes.map((n) => n.offsetLeft + n.offsetWidth));
    const maxY = Math.max(...nodes.map((n) => n.offsetTop + n.offsetHeight));
    this.container.classList.remove('sizing');
    const margin = 24;
    const zoom = Math.min(1, (this.container.clientWidth - 2 * margin) / (maxX - minX), (this.container.clientHeight - 2 * margin) / (maxY - minY));
    this.df.zoom = Math.max(this.floorZoom, zoom);
    this.df.canvas_x = margin - minX * this.df.zoom;
    this.df.canvas_y = margin - minY * this.df.zoom;
    this.df.precanvas.style.transform = `translate(${this.df.canvas_x}px, ${this.df.canvas_y}px) scale(${this.df.zoom})`;
    (this.df as unknown as { zoom_last_value: number }).zoom_last_value = this.df.zoom;
    this.showZoom();
  }

  /** Back to zoom 1 with the canvas origin at the top left (a new graph). */
  resetView(): void {
    this.df.zoom = 1;
    this.df.canvas_x = 0;
    this.df.canvas_y = 0;
    this.df.precanvas.style.transform = 'translate(0px, 0px) scale(1)';
    (this.df as unknown as { zoom_last_value: number }).zoom_last_value = 1;
    this.showZoom();
  }

  /**
   * Each wire gets a wide invisible twin path, drawn above the nodes' bodies (below their titles and port dots): a
   * click near a wire picks it even where it passes over a node. drawflow picks a wire by its path's first class.
   */
  private addHitPaths(): void {
    this.container.querySelectorAll<SVGSVGElement>('svg.connection').forEach((svg) => {
      const main = svg.querySelector('.main-path');
      if (!main) return;
      const hit = document.createElementNS('http://www.w3.org/2000/svg', 'path');
      hit.classList.add('main-path', 'gn-hit');
      hit.setAttribute('d', main.getAttribute('d') ?? '');
      svg.append(hit);
    });
  }

  /**
   * From the drawn nodes: the zoom from which their smallest label is readable (below it the canvas is compact), and
   * the zoom below which a node's name would not fit its node at titlePx (broken after its underscores).
   */
  private measureReadability(): void {
    const sizes = ['.gn-name', '.gn-type', '.gn-pname', '.gn-unit', '.gn-live', '.gn-problems'].flatMap((c) => {
      const e = this.container.querySelector(c);
      return e ? [parseFloat(getComputedStyle(e).fontSize)] : [];
    });
    this.fullZoom = sizes.length === 0 ? 1 : readablePx / Math.min(...sizes);
    const title = this.container.querySelector('.gn-title');
    const measure = document.createElement('canvas').getContext('2d');
    let floor = zoomMin;
    if (title && measure) {
      const style = getComputedStyle(title);
      measure.font = `${style.fontWeight} ${titlePx}px ${style.fontFamily}`;
      for (const [name] of this.ids) {
        const e = this.nodeElement(name);
        const widest = Math.max(...name.split(/(?<=_)/).map((piece) => measure.measureText(piece).width));
        if (e) floor = Math.max(floor, (widest + 12) / e.offsetWidth);
      }
    }
    this.floorZoom = Math.min(1, floor);
    this.df.zoom_min = this.floorZoom;
    this.showZoom();
  }

  /** Compact below the zoom that keeps labels readable; the name's size follows the zoom (titlePx on screen). */
  private showZoom(): void {
    this.container.classList.toggle('compact', this.df.zoom < this.fullZoom);
    this.container.style.setProperty('--gn-title-size', `${titlePx / this.df.zoom}px`);
  }

  /** Canvas coordinates of a point on the screen (for dropping from the palette). */
  toCanvas(clientX: number, clientY: number): { x: number; y: number } {
    const r = this.container.getBoundingClientRect();
    return { x: (clientX - r.left - this.df.canvas_x) / this.df.zoom, y: (clientY - r.top - this.df.canvas_y) / this.df.zoom };
  }

  pick(s: Selection): void {
    this.picked = s;
    this.markPicked();
  }

  private select(s: Selection): void {
    if (this.rendering) return;
    this.pick(s);
    this.onSelect(s);
  }

  private markPicked(): void {
    this.container.querySelectorAll('.picked').forEach((e) => e.classList.remove('picked'));
    const s = this.picked;
    if (s && 'node' in s) this.nodeElement(s.node)?.classList.add('picked');
    if (s && 'wire' in s) this.wireElement(s.wire)?.classList.add('picked');
  }

  private addNode(name: string, type: string, x: number, y: number): void {
    const ports = this.portsOf(name) ?? { inputs: [], outputs: [] };
    const row = (dir: 'in' | 'out', p: { name: string; units: string; description: string }) => {
      const signal = `${name}.${p.name}`;
      return `<div class="gn-port" data-dir="${dir}" data-signal="${esc(signal)}" title="${esc(`${signal}${p.units ? ` (${p.units})` : ''}: ${p.description}`)}">`
        + `<span class="gn-pname">${esc(p.name)}</span>${p.units ? `<span class="gn-unit">${esc(p.units)}</span>` : ''}<span class="gn-live"></span></div>`;
    };
    const html = `<div class="gn-head"><span class="gn-name">${esc(name)}</span><span class="gn-type">${esc(type)}</span></div>`
      + `<div class="gn-body"><div class="gn-ins">${ports.inputs.map((p) => row('in', p)).join('')}</div>`
      + `<div class="gn-outs">${ports.outputs.map((p) => row('out', p)).join('')}</div></div><div class="gn-problems"></div>`
      + `<div class="gn-title"><span>${esc(name).replace(/_/g, '_<wbr>')}</span></div>`;
    const id = this.df.addNode(name, ports.inputs.length, ports.outputs.length, x, y, `gn${name === robotInstance ? ' gn-robot' : ''}`, {}, html);
    this.ids.set(name, id);
    this.names.set(id, name);
    const el = this.container.querySelector<HTMLElement>(`#node-${id}`)!;
    el.dataset.instance = name;
    el.querySelectorAll<HTMLElement>('.inputs .input').forEach((d, i) => { d.dataset.signal = `${name}.${ports.inputs[i].name}`; });
    el.querySelectorAll<HTMLElement>('.outputs .output').forEach((d, i) => { d.dataset.signal = `${name}.${ports.outputs[i].name}`; });
    // Rows wider than the default node: let the node size itself, and line the port dots up with their rows.
    el.style.setProperty('--rows-in', String(ports.inputs.length));
  }

  private endsOf(from: string, to: string): { out: number; in: number; outClass: string; inClass: string } | null {
    const out = this.ids.get(instanceOf(from));
    const inId = this.ids.get(instanceOf(to));
    if (out === undefined || inId === undefined) return null;
    const o = this.portsOf(instanceOf(from))?.outputs.findIndex((p) => p.name === portOf(from)) ?? -1;
    const i = this.portsOf(instanceOf(to))?.inputs.findIndex((p) => p.name === portOf(to)) ?? -1;
    return o < 0 || i < 0 ? null : { out, in: inId, outClass: `output_${o + 1}`, inClass: `input_${i + 1}` };
  }

  private signalOf(id: string, cls: string, dir: 'inputs' | 'outputs'): string | null {
    const name = this.names.get(Number(id));
    const index = Number(cls.split('_')[1]) - 1;
    const port = name === undefined ? undefined : this.portsOf(name)?.[dir][index];
    return port && name !== undefined ? `${name}.${port.name}` : null;
  }

  private wireIndex(e: ConnectionEvent): number {
    const from = this.signalOf(e.output_id, e.output_class, 'outputs');
    const to = this.signalOf(e.input_id, e.input_class, 'inputs');
    return this.graph.wires.findIndex((w) => w.from === from && w.to === to);
  }

  private connected(e: ConnectionEvent): void {
    if (this.rendering) return;
    const from = this.signalOf(e.output_id, e.output_class, 'outputs');
    const to = this.signalOf(e.input_id, e.input_class, 'inputs');
    if (from && to) this.history.change((g) => g.wires.push({ from, to, delayed: false }));
  }

  private moved(id: string): void {
    const name = this.names.get(Number(id));
    const node = this.df.getNodeFromId(id);
    if (name === undefined) return;
    this.history.change((g) => {
      if (name === robotInstance) {
        g.robotX = node.pos_x;
        g.robotY = node.pos_y;
        return;
      }
      const i = g.instances.find((x) => x.name === name);
      if (i) {
        i.x = node.pos_x;
        i.y = node.pos_y;
      }
    });
  }
}

export function formatValue(v: number): string {
  if (!Number.isFinite(v)) return String(v);
  const a = Math.abs(v);
  if (a < 1e-9) return '0.000';
  return a !== 0 && (a < 0.01 || a >= 1e5) ? v.toExponential(2) : v.toFixed(a < 10 ? 3 : a < 1000 ? 2 : 0);
}
