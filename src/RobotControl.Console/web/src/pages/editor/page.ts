// Graph editor page: palette of the catalog's plug-in types, the node canvas (drawflow), the settings pane, problems
// from the graph-file loader itself (POST /api/editor/check), load/save of the graphs folder, undo/redo, start/stop
// of the edited graph and live values while it runs.
import { api, act, ApiError, markFirstValue, show } from '../../api';
import { el, button } from '../../dom';
import { SignalStream } from '../../stream';
import { GraphCanvas, type Selection } from './canvas';
import { type Catalog, type NodePorts, type Problem, History, emptyGraph, freshName, fromFile, problemTarget, robotInstance, targetName, toFile } from './model';
import { markFields, removeNode, renderSide } from './side';
import { clearDraft, readDraft, writeDraft } from './draft';
import './editor.css';

interface RunView { running: boolean; graph: string | null; transport: string; problem: string | null }

export function editorPage(root: HTMLElement): () => void {
  const graphs = el('select', { 'data-testid': 'graph-list', 'aria-label': 'graph file to load' });
  const fileName = el('input', { 'data-testid': 'file-name', 'aria-label': 'file name to save as', value: 'untitled.json', spellcheck: 'false', size: '18' });
  const undo = button('Undo', () => step(false), { title: 'Ctrl+Z', 'data-testid': 'undo' });
  const redo = button('Redo', () => step(true), { title: 'Ctrl+Shift+Z', 'data-testid': 'redo' });
  const start = button('Start', () => void startGraph(), { class: 'primary', 'data-testid': 'start' });
  const stop = button('Stop', () => void act(async () => { await api('POST', '/editor/stop'); await refreshRun(); return { message: 'stopped: motors off' }; }), { 'data-testid': 'stop' });
  const runState = el('span', { class: 'run-state', 'data-testid': 'run-state' });
  const unsaved = el('span', { class: 'unsaved', 'data-testid': 'unsaved', hidden: '' }, 'unsaved edits');
  const palette = el('aside', { class: 'ged-palette', 'data-testid': 'palette' });
  const canvasBox = el('div', { class: 'ged-canvas', 'data-testid': 'graph-canvas' });
  const pane = el('div', { class: 'ged-pane', 'data-testid': 'side-pane' });
  const problemList = el('div', { class: 'ged-problems', 'data-testid': 'problems' });
  root.append(el('div', { class: 'ged' },
    el('div', { class: 'toolbar ged-toolbar' },
      graphs, button('Load', () => void load(graphs.value), { 'data-testid': 'load' }), button('New', () => fresh(), { 'data-testid': 'new' }),
      el('span', { class: 'sep' }), fileName, button('Save', () => void save(), { 'data-testid': 'save', 'data-operator': '' }), unsaved,
      el('span', { class: 'sep' }), undo, redo, button('Fit', () => canvas.fit()),
      el('span', { class: 'sep' }), start, stop, runState),
    el('div', { class: 'ged-main' }, palette, canvasBox, el('aside', { class: 'ged-side' }, pane, problemList))));

  let catalog: Catalog = { types: [], robot: null, robotFile: null, problems: [] };
  let selection: Selection = null;
  let problems: Problem[] = [];
  let checking = 0;
  let checkTimer = 0;
  let run: RunView | null = null;
  // The file as it was last loaded or saved (toFile's JSON), and its name: the edits since are unsaved, and kept as a
  // draft in this browser until saved or discarded.
  let baseline = '';
  let loadedName = '';
  const isDirty = () => JSON.stringify(toFile(history.graph)) !== baseline;
  const history = new History(emptyGraph(null), () => changed());
  baseline = JSON.stringify(toFile(history.graph)); // nothing to lose yet
  // A node's ports: as the last check created the instance with its settings, else the type's with default settings.
  let instancePorts: Record<string, NodePorts> = {};
  const portsOf = (name: string): NodePorts | null => instancePorts[name] ?? (name === robotInstance
    ? catalog.robot
    : null) ?? catalog.types.find((t) => t.name === history.graph.instances.find((i) => i.name === name)?.type)?.ports ?? null;
  const canvas = new GraphCanvas(canvasBox, history, portsOf, (s) => { selection = s; side(); });

  function changed(): void {
    if (selection && 'node' in selection && selection.node !== robotInstance && !history.graph.instances.some((i) => i.name === (selection as { node: string }).node)) selection = null;
    if (selection && 'wire' in selection && !history.graph.wires[selection.wire]) selection = null;
    canvas.pick(selection);
    canvas.render();
    problems = [];
    decorate();
    side();
    keepDraft();
    undo.disabled = !history.canUndo;
    redo.disabled = !history.canRedo;
    clearTimeout(checkTimer);
    checking++;
    start.disabled = true;
    delete problemList.dataset.count;
    checkTimer = window.setTimeout(() => void check(), 150);
  }

  async function check(): Promise<void> {
    const mine = checking;
    const reply = await api<{ problems: Problem[]; ports: Record<string, NodePorts> }>('POST', '/editor/check', { name: fileName.value, graph: toFile(history.graph) })
      .catch((e: ApiError) => ({ problems: [{ path: '$', message: e.message }], ports: instancePorts }));
    if (mine !== checking) return;
    problems = reply.problems;
    const editing = pane.contains(document.activeElement);
    if (JSON.stringify(reply.ports) !== JSON.stringify(instancePorts)) {
      instancePorts = reply.ports;
      canvas.renderWhenIdle(() => {
        if (canvas.separate()) canvas.render();
        decorate();
      });
    }
    decorate();
    // Rebuilding the pane under the user's cursor would drop what they type: then only mark the fields.
    if (editing) markFields(pane, selection, history.graph, problems); else side();
    start.disabled = problems.length > 0;
    problemList.dataset.count = String(problems.length); // set once the server has checked this version
    start.title = problems.length > 0 ? 'fix the problems first' : 'save and run this graph';
    canvasBox.dataset.checked = String(mine);
  }

  // Every problem of the last check, each under the node or wire it names (a click picks that node or wire).
  function decorate(): void {
    const rest = canvas.decorate(problems);
    problemList.replaceChildren(el('h3', {}, problems.length === 0 ? 'No problems' : `${problems.length} problem${problems.length === 1 ? '' : 's'}`),
      ...problems.map((p) => {
        const target = problemTarget(history.graph, p);
        const line = el('div', { class: rest.includes(p) ? 'problem' : 'problem placed' },
          ...(target ? [el('strong', { class: 'target' }, targetName(history.graph, target)), ' '] : []), `${p.path}: ${p.message}`);
        if (target) {
          line.addEventListener('click', () => {
            selection = target;
            canvas.pick(selection);
            side();
          });
        }
        return line;
      }));
  }

  function side(): void {
    renderSide(pane, selection, history, catalog, problems, (next) => { selection = next; });
  }

  function step(forward: boolean): void {
    if (forward) history.redo(); else history.undo();
  }

  /** The edits since the last load or save, kept (or the draft dropped when there are none). */
  function keepDraft(): void {
    const dirty = isDirty();
    unsaved.hidden = !dirty;
    if (dirty) writeDraft({ fileName: fileName.value.trim(), baseline, loadedName, history: history.state, at: Date.now() });
    else clearDraft();
  }

  /** True when there are no unsaved edits, or the user agreed to drop them. */
  function mayDiscard(): boolean {
    return !isDirty() || confirm(`Discard the unsaved edits of ${fileName.value.trim()}? (Cancel keeps them.)`);
  }

  /** The graph just loaded or saved under <name> is what unsaved edits are measured against. */
  function saved(name: string): void {
    baseline = JSON.stringify(toFile(history.graph));
    loadedName = name;
    keepDraft();
  }

  function fresh(): void {
    if (!mayDiscard()) return;
    selection = null;
    fileName.value = 'untitled.json';
    canvas.resetView();
    history.reset(emptyGraph(catalog.robotFile));
    saved('');
  }

  async function load(name: string): Promise<void> {
    if (!name || !mayDiscard()) return;
    await act(async () => {
      const file = await api<Record<string, unknown>>('GET', `/editor/graphs/${encodeURIComponent(name)}`);
      selection = null;
      fileName.value = name;
      history.reset(fromFile(file));
      await check(); // each instance's ports, so the nodes are drawn at their size before they are laid out
      if (canvas.layOut()) history.reset(history.graph);
      canvas.fit();
      saved(name);
      return { message: `loaded ${name}` };
    });
  }

  /** Takes up the draft this browser kept (unsaved edits of an earlier visit), with its undo history. */
  async function resume(): Promise<boolean> {
    const draft = readDraft();
    if (!draft) return false;
    selection = null;
    fileName.value = draft.fileName;
    baseline = draft.baseline;
    loadedName = draft.loadedName;
    history.restore(draft.history);
    await check();
    canvas.fit();
    show(`restored the unsaved edits of ${draft.fileName} from ${new Date(draft.at).toLocaleTimeString()} (kept in this browser): Save keeps them, Load or New discards them`);
    return true;
  }

  async function save(): Promise<boolean> {
    const name = fileName.value.trim();
    if (name !== loadedName && [...graphs.options].some((o) => o.value === name) && !confirm(`${name} exists: overwrite it?`)) return false;
    return act(async () => {
      const reply = await api<{ message: string }>('PUT', `/editor/graphs/${encodeURIComponent(name)}`, { graph: toFile(history.graph) });
      saved(name);
      await listGraphs(name);
      return reply;
    });
  }

  async function startGraph(): Promise<void> {
    await act(async () => {
      const reply = await api<RunView>('POST', '/editor/start', { name: fileName.value.trim(), graph: toFile(history.graph) });
      saved(fileName.value.trim()); // Start saved it
      await listGraphs(fileName.value.trim());
      await refreshRun();
      return { message: `${reply.graph} runs on ${reply.transport}` };
    });
  }

  async function listGraphs(select?: string): Promise<void> {
    const reply = await api<{ folder: string; graphs: string[] }>('GET', '/editor/graphs');
    graphs.replaceChildren(...reply.graphs.map((g) => el('option', { value: g }, `${reply.folder}/${g}`)));
    if (select && reply.graphs.includes(select)) graphs.value = select;
  }

  // Live values: while the edited file runs, every output of the graph streams from the session's signal ring.
  // A socket streams the ring of the session it connected to: each started graph gets a new socket.
  let latest: Map<string, number> | null = null;
  let stream: SignalStream | null = null;
  const onFrame = (names: string[], frame: { t: number[]; v: number[][] }) => {
    // One column per signal: the newest value of each is the column's last.
    if (frame.t.length === 0) return;
    latest = new Map(names.map((n, i) => [n, frame.v[i][frame.v[i].length - 1]]));
  };
  let subscribed = '';
  const paint = setInterval(() => canvas.showLive(run?.running && run.graph === fileName.value.trim() ? latest : null), 100);

  async function refreshRun(): Promise<void> {
    run = await api<RunView>('GET', '/editor/run');
    runState.textContent = run.running ? `running ${run.graph} on ${run.transport}` : run.problem ? `stopped: ${run.problem}` : 'stopped';
    runState.dataset.running = String(run.running);
    stop.disabled = !run.running;
    if (!run.running) canvas.showLive(null);
    const key = run.running ? `${run.graph}` : '';
    if (key !== subscribed) {
      subscribed = key;
      latest = null;
      stream?.close();
      stream = null;
      if (run.running) {
        const signals = await api<{ name: string }[]>('GET', '/signals');
        stream = new SignalStream(onFrame, 20);
        stream.subscribe(signals.map((s) => s.name));
      }
    }
  }
  const runTimer = setInterval(() => void refreshRun().catch(() => undefined), 1000);

  const onKey = (e: KeyboardEvent) => {
    const typing = e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement || e.target instanceof HTMLTextAreaElement;
    if ((e.ctrlKey || e.metaKey) && e.key.toLowerCase() === 'z' && !typing) {
      e.preventDefault();
      step(e.shiftKey);
    } else if ((e.ctrlKey || e.metaKey) && e.key.toLowerCase() === 'y' && !typing) {
      e.preventDefault();
      step(true);
    } else if ((e.key === 'Delete' || e.key === 'Backspace') && !typing && selection) {
      const s = selection;
      e.preventDefault();
      if ('wire' in s) history.change((m) => { m.wires.splice(s.wire, 1); });
      else if (s.node !== robotInstance) removeNode(history, s.node);
    }
  };
  document.addEventListener('keydown', onKey);
  // Closing or reloading the tab with unsaved edits: the browser asks (the draft keeps them either way).
  const onLeave = (e: BeforeUnloadEvent) => {
    if (isDirty()) e.preventDefault();
  };
  window.addEventListener('beforeunload', onLeave);

  // Palette: click adds a node in view; drag drops it where it lands.
  function add(type: string, at?: { x: number; y: number }): void {
    const g = history.graph;
    const name = freshName(g, type);
    // Without a drop point: the next of 4 columns of the view (the robot sits right of them), below what is there.
    const n = g.instances.length;
    const box = canvasBox.getBoundingClientRect();
    const column = canvas.toCanvas(box.left + 30 + (n % 4) * 330, box.top + 20);
    const spot = at ?? { x: column.x, y: canvas.freeTop(column.x, column.y) };
    history.change((m) => m.instances.push({ name, type, settings: {}, x: spot.x, y: spot.y }));
    selection = { node: name };
    canvas.pick(selection);
    side();
  }
  canvasBox.addEventListener('dragover', (e) => e.preventDefault());
  canvasBox.addEventListener('drop', (e) => {
    e.preventDefault();
    const type = e.dataTransfer?.getData('text/plugin-type');
    if (type) add(type, canvas.toCanvas(e.clientX, e.clientY));
  });

  void (async () => {
    try {
      // The three reads do not depend on each other: asked together, the page waits for the slowest, not their sum.
      [catalog] = await Promise.all([api<Catalog>('GET', '/editor/catalog'), listGraphs(), refreshRun()]);
      palette.replaceChildren(el('h3', {}, 'Plug-in types'), ...catalog.types.map((t) => {
        const item = el('button', { type: 'button', class: 'ged-type', draggable: 'true', 'data-type': t.name, title: t.portsProblem ?? t.description },
          el('strong', {}, t.name), el('small', {}, t.description), el('small', { class: 'origin' }, t.assembly));
        item.addEventListener('click', () => add(t.name));
        item.addEventListener('dragstart', (e) => e.dataTransfer?.setData('text/plugin-type', t.name));
        return item;
      }), ...catalog.problems.map((p) => el('p', { class: 'problem' }, p)));
      const running = (run as RunView | null)?.graph;
      if (await resume()) {
        // the draft, not the running graph
      } else if (running) {
        graphs.value = running;
        await load(running);
      } else {
        fresh();
      }
      markFirstValue(root); // the graph drawn (the start-up measurement)
    } catch (e) {
      show((e as Error).message, true);
    }
  })();

  return () => {
    clearInterval(paint);
    clearInterval(runTimer);
    clearTimeout(checkTimer);
    stream?.close();
    document.removeEventListener('keydown', onKey);
    window.removeEventListener('beforeunload', onLeave);
  };
}
