import { el } from '../dom';
import type { FaultView } from './types';

// Faults in plain words; the raw detail (check, value, limit, action, time) one click away.
export function faultsPanel(): { element: HTMLElement; show: (faults: FaultView[]) => void } {
  const list = el('div', { class: 'fault-list', 'data-testid': 'faults' });
  const element = el('section', { class: 'faults' }, list);
  let shown = '';
  const open = new Set<string>();
  return {
    element,
    show(faults) {
      const key = JSON.stringify(faults);
      if (key === shown) return;
      shown = key;
      element.classList.toggle('active', faults.length > 0);
      if (faults.length === 0) {
        list.replaceChildren(el('span', { class: 'no-faults', 'data-testid': 'no-faults' }, 'No faults'));
        return;
      }
      list.replaceChildren(...[...faults].reverse().map((f) => {
        const id = `${f.timeSeconds}-${f.check}-${f.subject}`;
        const detail = el('div', { class: 'fault-detail', 'data-testid': 'fault-detail' },
          `check ${f.check}${f.subject ? ` · ${f.subject}` : ''} · measured ${num(f.measured)} ${f.unit} · limit ${num(f.limit)} ${f.unit} · action ${f.action} · at ${num(f.timeSeconds)} s`);
        detail.hidden = !open.has(id);
        const words = el('button', { type: 'button', class: 'fault-words', 'data-testid': 'fault', 'aria-expanded': String(open.has(id)) }, f.words);
        words.addEventListener('click', () => {
          detail.hidden = !detail.hidden;
          if (detail.hidden) open.delete(id); else open.add(id);
          words.setAttribute('aria-expanded', String(!detail.hidden));
        });
        return el('div', { class: 'fault' }, words, detail);
      }));
    },
  };
}

/** Up to three decimals, without trailing zeros. */
function num(v: number): string {
  return Number.isFinite(v) ? String(Number(v.toFixed(3))) : String(v);
}
