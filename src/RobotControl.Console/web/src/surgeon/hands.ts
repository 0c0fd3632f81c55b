import { act, api } from '../api';
import { button, el, fmt } from '../dom';
import type { FaultView, HandView, Latest, PedalView } from './types';

// Per hand: clutch, haptic lock, scale factor (changed only while that hand's clutch is held: the server refuses
// otherwise) and haptic-wall proximity; and the pedals with what each drives.
export interface HandsPanel {
  element: HTMLElement;
  update: (latest: Latest, wallMm: (arm: string) => number | null, operator: boolean) => void;
  refresh: (hands: HandView[]) => void;
  /** Each arm's state: its own newest fault since the last reset, else what the run level does to every arm. */
  states: (faults: FaultView[], level: string) => void;
}

// What a run level means for an arm without a fault of its own: one word legible from 2 m, and a line on what it means.
const armAt: Record<string, [string, string]> = {
  PEDAL_DOWN: ['FOLLOWING', 'following the hand'], PEDAL_UP: ['HOLDING', 'holding: press the pedal'], HOMING: ['HOMING', 'homing from the pots'],
  INIT: ['MOTORS OFF', 'not homed: Home the arms'], E_STOP: ['STOPPED', 'motors off after the E-STOP'],
};

export function handsPanel(hands: HandView[], pedals: PedalView[]): HandsPanel {
  const cards = hands.map((hand) => handCard(hand));
  const pedalChips = pedals.map((p) => {
    const state = el('b', { 'data-testid': `pedal-state-${p.signal}` }, '—');
    return { pedal: p, state, element: el('div', { class: 'pedal', 'data-testid': `pedal-${p.signal}` }, el('span', {}, `${p.signal.split('.').pop()} · ${p.drives}`), state) };
  });
  const element = el('section', { class: 'hands' },
    el('div', { class: 'hand-row' }, ...cards.map((c) => c.element)),
    el('div', { class: 'pedals' }, ...(pedalChips.length > 0 ? pedalChips.map((c) => c.element) : [el('span', { class: 'dim' }, 'no foot pedals in the graph')])));
  return {
    element,
    update(latest, wallMm, operator) {
      cards.forEach((c) => c.update(latest, wallMm(c.hand.arm), operator));
      for (const c of pedalChips) {
        const down = (latest(c.pedal.signal) ?? 0) >= 0.5;
        c.state.textContent = down ? 'PRESSED' : 'up';
        c.element.classList.toggle('on', down);
      }
    },
    refresh(next) {
      for (const h of next) cards.find((c) => c.hand.arm === h.arm)?.refresh(h);
    },
    states(faults, level) {
      for (const c of cards) c.state(faults.filter((f) => f.arm === c.hand.arm).pop() ?? null, level);
    },
  };
}

function handCard(initial: HandView) {
  let hand = initial;
  const arm = hand.arm;
  const clutch = el('b', { 'data-testid': `clutch-${arm}` }, '—');
  const lock = el('b', { 'data-testid': `lock-${arm}` }, hand.lockSignal ? '—' : 'none');
  const scale = el('b', { class: 'scale', 'data-testid': `scale-${arm}` }, fmt(hand.scale ?? Number.NaN, 2));
  const input = el('input', { type: 'number', class: 'narrow', step: '0.05', min: String(hand.scaleMin), max: String(hand.scaleMax), 'aria-label': `scale factor of the ${arm} hand` });
  const set = async (value: number) => act(async () => {
    const reply = await api<{ message: string }>('PUT', `/hands/${arm}/scale`, { value: Math.round(value * 1000) / 1000 });
    scale.textContent = fmt(value, 2);
    return reply;
  });
  const minus = button('−', () => void set((hand.scale ?? 1) - 0.1), { 'data-testid': `scale-down-${arm}`, 'aria-label': `smaller ${arm} scale` });
  const plus = button('+', () => void set((hand.scale ?? 1) + 0.1), { 'data-testid': `scale-up-${arm}`, 'aria-label': `larger ${arm} scale` });
  const apply = button('Set', () => void set(Number(input.value)), { 'data-testid': `scale-set-${arm}` });
  const hint = el('span', { class: 'dim', 'data-testid': `scale-hint-${arm}` });
  const armState = el('div', { class: 'arm-state', 'data-testid': `arm-${arm}` }, '—');
  const armWhy = el('div', { class: 'arm-why', 'data-testid': `arm-why-${arm}` });
  const wall = el('b', { 'data-testid': `wall-${arm}` }, '—');
  const meter = el('meter', { min: '0', max: '1', value: '0', 'aria-label': `${arm} wall force` });
  const element = el('div', { class: 'hand', 'data-testid': `hand-${arm}` },
    el('h2', {}, `${arm[0].toUpperCase()}${arm.slice(1)} arm`),
    armState, armWhy,
    el('div', { class: 'hand-grid' },
      el('span', {}, 'Clutch'), clutch,
      el('span', {}, 'Haptic lock'), lock,
      el('span', {}, 'Scale'), el('span', { class: 'scale-row' }, scale, minus, plus, input, apply),
      el('span', {}, 'Wall'), el('span', { class: 'wall-row' }, wall, meter)),
    hint);

  return {
    hand: initial,
    element,
    state(fault: FaultView | null, level: string) {
      const [word, why] = fault ? ['FAULT', fault.words] : armAt[level] ?? [level, ''];
      armState.textContent = word;
      armWhy.textContent = why;
      armState.dataset.state = fault ? 'fault' : level;
      element.classList.toggle('faulted', fault !== null);
    },
    refresh(next: HandView) {
      hand = next;
      if (document.activeElement !== input) scale.textContent = fmt(next.scale ?? Number.NaN, 2);
    },
    update(latest: Latest, wallMm: number | null, operator: boolean) {
      const held = hand.clutchSignal !== null && (latest(hand.clutchSignal) ?? 0) >= 0.5;
      clutch.textContent = hand.clutchSignal === null ? 'none' : held ? 'HELD' : 'released';
      clutch.classList.toggle('on', held);
      if (hand.lockSignal) {
        const locked = (latest(hand.lockSignal) ?? 0) >= 0.5;
        lock.textContent = locked ? 'LOCKED' : 'free';
        lock.classList.toggle('on', locked);
      }
      const can = held && operator && hand.scaleSettable;
      for (const b of [minus, plus, apply, input]) b.disabled = !can;
      hint.textContent = !hand.scaleSettable ? 'the scale is set by the graph'
        : !operator ? 'take the operator role to change the scale' : held ? '' : 'hold the clutch to change the scale';
      const force = hand.wallSignals.map((s) => latest(s) ?? 0);
      const magnitude = Math.hypot(...force);
      const past = hand.reachErrorSignal ? latest(hand.reachErrorSignal) ?? 0 : 0;
      meter.value = hand.wallMaxForceN > 0 ? Math.min(1, magnitude / hand.wallMaxForceN) : 0;
      wall.textContent = magnitude > 0.01
        ? `AT WALL · ${fmt(past, 1)} mm past · ${fmt(magnitude, 2)} N`
        : wallMm === null ? 'clear' : `${fmt(wallMm, 0)} mm to wall`;
      element.classList.toggle('at-wall', magnitude > 0.01);
    },
  };
}
