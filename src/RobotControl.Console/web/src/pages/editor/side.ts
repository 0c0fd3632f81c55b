// The side pane: the picked node's name and settings (generated from its type's settings schema), the picked wire
// (delayed or not), or the graph itself; and the problems that concern no node or wire.
import { el, button } from '../../dom';
import type { Selection } from './canvas';
import { type Catalog, type GraphModel, type History, type Problem, type SettingView, removeInstance, rename, robotInstance, wiresAt } from './model';

export function renderSide(root: HTMLElement, s: Selection, history: History, catalog: Catalog, problems: Problem[], reselect: (s: Selection) => void): void {
  const g = history.graph;
  if (s && 'node' in s && s.node === robotInstance) {
    root.replaceChildren(el('h3', {}, 'robot'), el('p', { class: 'hint' }, `The robot's node (${g.robot ?? ''}): its inputs drive the joints, its outputs report the robot.`),
      ...wires(g, robotInstance, history));
  } else if (s && 'node' in s) {
    const i = g.instances.find((x) => x.name === s.node);
    const type = catalog.types.find((t) => t.name === i?.type);
    if (!i) return renderSide(root, null, history, catalog, problems, reselect);
    const index = g.instances.indexOf(i);
    const name = el('input', { value: i.name, 'data-testid': 'instance-name', spellcheck: 'false' });
    name.addEventListener('change', () => {
      const to = name.value.trim();
      if (!to || to === i.name) return;
      reselect({ node: to });
      history.change((m) => rename(m, i.name, to));
    });
    const mine = problems.filter((p) => p.path.startsWith(`$.instances[${index}]`));
    root.replaceChildren(
      el('h3', {}, i.type),
      el('p', { class: 'hint' }, type?.description ?? 'unknown type'),
      el('label', { class: 'field' }, el('span', {}, 'name'), name),
      ...(type?.settings ?? []).map((setting) => field(setting, i.settings[setting.name], mine.find((p) => p.path === `$.instances[${index}].settings.${setting.name}`), (v) =>
        history.change((m) => {
          const target = m.instances.find((x) => x.name === i.name)!;
          if (v === undefined) delete target.settings[setting.name];
          else target.settings[setting.name] = v;
        }))),
      ...wires(g, i.name, history),
      el('div', { class: 'pane-actions' }, button('Delete node', () => removeNode(history, i.name), { 'data-testid': 'delete-node' })));
  } else if (s && 'wire' in s && g.wires[s.wire]) {
    const w = g.wires[s.wire];
    const delayed = el('input', { type: 'checkbox', 'data-testid': 'wire-delayed' });
    delayed.checked = w.delayed;
    delayed.addEventListener('change', () => history.change((m) => { m.wires[s.wire].delayed = delayed.checked; }));
    root.replaceChildren(
      el('h3', {}, 'Wire'),
      el('p', { class: 'mono' }, `${w.from} → ${w.to}`),
      el('label', { class: 'check' }, delayed, el('span', {}, 'delayed: the input gets the value of the previous tick (closes a cycle)')),
      ...problems.filter((p) => p.path.startsWith(`$.wires[${s.wire}]`)).map((p) => el('p', { class: 'problem' }, `${p.path}: ${p.message}`)),
      el('div', { class: 'pane-actions' }, button('Delete wire', () => history.change((m) => { m.wires.splice(s.wire, 1); }), { 'data-testid': 'delete-wire' })));
  } else {
    root.replaceChildren(
      el('h3', {}, 'Graph'),
      el('p', { class: 'hint' }, 'Pick a node to edit its settings, a wire to mark it delayed. Drag from an output (right) to an input (left) to wire them.'),
      el('table', { class: 'kv' },
        el('tr', {}, el('th', {}, 'robot'), el('td', {}, g.robot ?? 'none')),
        el('tr', {}, el('th', {}, 'transport'), el('td', {}, g.transport)),
        el('tr', {}, el('th', {}, 'loop rate'), el('td', {}, `${g.loopRateHz} Hz`)),
        el('tr', {}, el('th', {}, 'nodes, wires'), el('td', {}, `${g.instances.length}, ${g.wires.length}`))));
  }
}

function field(s: SettingView, value: unknown, problem: Problem | undefined, set: (v: unknown) => void): HTMLElement {
  const range = s.minimum !== null || s.maximum !== null ? `${s.minimum ?? '−∞'} … ${s.maximum ?? '∞'}` : '';
  const meta = [s.units, range, s.required ? 'required' : `default ${JSON.stringify(s.default)}`].filter(Boolean).join(' · ');
  let input: HTMLInputElement | HTMLSelectElement;
  if (s.kind === 'boolean' || s.kind === 'choice') {
    const options = s.kind === 'boolean' ? ['true', 'false'] : s.choices;
    input = el('select', {}, el('option', { value: '' }, `(default: ${String(s.default)})`), ...options.map((o) => el('option', { value: o }, o)));
    input.value = value === undefined ? '' : String(value);
    input.addEventListener('change', () => set(input.value === '' ? undefined : s.kind === 'boolean' ? input.value === 'true' : input.value));
  } else {
    const numeric = s.kind === 'number' || s.kind === 'integer';
    input = el('input', { type: numeric ? 'number' : 'text', step: s.kind === 'integer' ? '1' : 'any', placeholder: s.default === null || s.default === undefined ? '' : String(s.default), spellcheck: 'false' });
    if (numeric && s.minimum !== null) input.setAttribute('min', String(s.minimum));
    if (numeric && s.maximum !== null) input.setAttribute('max', String(s.maximum));
    input.value = value === undefined ? '' : String(value);
    input.addEventListener('change', () => {
      const text = input.value.trim();
      set(text === '' ? undefined : numeric && Number.isFinite(Number(text)) ? Number(text) : text);
    });
  }
  input.dataset.setting = s.name;
  return el('label', { class: `field${problem ? ' bad' : ''}`, title: s.description },
    el('span', {}, s.name, el('small', {}, meta)), input, el('small', { class: 'desc' }, s.description),
    ...(problem ? [el('small', { class: 'problem', 'data-testid': 'setting-problem' }, `${problem.path}: ${problem.message}`)] : []));
}

/** The node's wires, each with its delayed switch. */
function wires(g: GraphModel, name: string, history: History): HTMLElement[] {
  const mine = g.wires.map((w, index) => ({ w, index })).filter(({ w }) => w.from.startsWith(`${name}.`) || w.to.startsWith(`${name}.`));
  if (mine.length === 0) return [];
  return [el('h4', {}, 'Wires (delayed: fed back one tick later)'), el('div', { class: 'wires' }, ...mine.map(({ w, index }) => {
    const box = el('input', { type: 'checkbox', 'data-wire': `${w.from}->${w.to}`, title: 'delayed' });
    box.checked = w.delayed;
    box.addEventListener('change', () => history.change((m) => { m.wires[index].delayed = box.checked; }));
    return el('label', { class: `check mono${w.delayed ? ' delayed' : ''}` }, box, el('span', {}, `${w.from} → ${w.to}`));
  }))];
}

/** Marks the picked node's setting fields that have a problem (without rebuilding the pane). */
export function markFields(root: HTMLElement, s: Selection, g: GraphModel, problems: Problem[]): void {
  const index = s && 'node' in s ? g.instances.findIndex((i) => i.name === s.node) : -1;
  root.querySelectorAll<HTMLElement>('[data-setting]').forEach((input) => {
    const problem = problems.find((p) => index >= 0 && p.path === `$.instances[${index}].settings.${input.dataset.setting}`);
    const label = input.closest('label')!;
    label.classList.toggle('bad', problem !== undefined);
    label.title = problem ? `${problem.path}: ${problem.message}` : '';
  });
}

/** Removes node <name>, and its wires after asking when it has any (one undo step); false when the user said no. */
export function removeNode(history: History, name: string): boolean {
  const n = wiresAt(history.graph, name).length;
  if (n > 0 && !confirm(`Delete node ${name} and its ${n} wire${n === 1 ? '' : 's'}?`)) return false;
  history.change((m) => removeInstance(m, name));
  return true;
}
