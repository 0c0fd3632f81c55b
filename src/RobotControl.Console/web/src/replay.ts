import { api, act } from './api';
import { el, fmt } from './dom';

interface TimelineEntry { sequence: number; timeSeconds: number; source: string; message: string }
interface ReplayView { positionS: number; durationS: number; session: string; timeline: TimelineEntry[]; truncated: string | null }

// The replay bar (robotctl console --replay): time slider, play/pause, 0.25x-4x, the run levels and trips on the
// timeline. Shown above every page when the console serves a recording (GET /api/replay answers); absent otherwise.
export async function replayBar(host: HTMLElement): Promise<void> {
  let view: ReplayView;
  try {
    view = await api<ReplayView>('GET', '/replay');
  } catch {
    return; // a live session: no replay
  }

  const slider = el('input', { type: 'range', min: '0', max: String(view.durationS), step: '0.001', value: '0', 'data-testid': 'replay-slider', 'aria-label': 'replay position' });
  const time = el('span', { 'data-testid': 'replay-time' });
  const play = el('button', { type: 'button', 'data-testid': 'replay-play' }, 'Pause');
  const rate = el('select', { 'data-testid': 'replay-rate', 'aria-label': 'replay rate' },
    ...['0.25', '0.5', '1', '2', '4'].map((r) => el('option', r === '1' ? { value: r, selected: '' } : { value: r }, `${r}x`)));
  const marks = el('div', { class: 'replay-marks', 'data-testid': 'replay-timeline' });
  for (const e of view.timeline) {
    const trip = e.message.startsWith('trip: ');
    marks.append(el('span', { class: trip ? 'mark trip' : 'mark level', style: `left: ${(100 * e.timeSeconds) / Math.max(view.durationS, 1e-9)}%`, title: `${fmt(e.timeSeconds, 3)} s ${e.message}` }, trip ? '▲' : '|'));
  }

  let dragging = false;
  function show(v: ReplayView): void {
    view = v;
    if (!dragging) slider.value = String(v.positionS);
    time.textContent = `${fmt(v.positionS, 3)} / ${fmt(v.durationS, 3)} s`;
    play.textContent = v.session.includes('paused') ? 'Play' : 'Pause';
  }

  async function post(body: Record<string, unknown>): Promise<void> {
    await act(async () => {
      show(await api<ReplayView>('POST', '/replay', body));
      return { message: view.session };
    });
  }

  slider.addEventListener('input', () => { dragging = true; });
  slider.addEventListener('change', () => { dragging = false; void post({ seek_s: Number(slider.value) }); });
  play.addEventListener('click', () => void post({ play: view.session.includes('paused') }));
  rate.addEventListener('change', () => void post({ rate: Number(rate.value) }));
  host.replaceChildren(el('div', { class: 'replay', 'data-testid': 'replay-bar' },
    el('strong', {}, 'Replay'), play, rate, el('div', { class: 'replay-track' }, slider, marks), time,
    view.truncated ? el('span', { class: 'error' }, view.truncated) : ''));
  host.hidden = false;
  show(view);
  setInterval(() => void api<ReplayView>('GET', '/replay').then(show).catch(() => undefined), 250);
}
