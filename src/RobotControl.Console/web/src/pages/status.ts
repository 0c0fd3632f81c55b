import { act, api, markFirstValue, onRestart, type StatusReply } from '../api';
import { button, el, fmt } from '../dom';
import { faultWords } from '../statusbar';
import type { SurgeonView } from '../surgeon/types';

interface EventEntry { sequence: number; timeSeconds: number; source: string; message: string }
interface Timing { component: string; count: number; medianUs: number; p99Us: number; maxUs: number }

// Run status: loop rate, tick time, deadline misses, bus counters, the fault and event log, per-component timing.
export function statusPage(root: HTMLElement): () => void {
  const summary = el('table', { class: 'kv', 'data-testid': 'run-status' });
  const timings = el('table', { class: 'timings' });
  const log = el('table', { class: 'log', 'data-testid': 'event-log' });
  let recording: string | null = null;
  const record = button('Record', () => void act(async () => {
    const reply = await api<{ message: string }>('POST', '/recording', { on: recording === null });
    await refreshRecording();
    return reply;
  }), { 'data-testid': 'record', 'data-operator': '' });
  const recordingText = el('span', { 'data-testid': 'recording-file' });
  async function refreshRecording(): Promise<void> {
    recording = (await api<{ recordingFile: string | null }>('GET', '/recording')).recordingFile;
    record.textContent = recording === null ? 'Record' : 'Stop recording';
    recordingText.textContent = recording === null ? 'not recording' : `recording to ${recording}`;
  }
  root.append(el('p', { class: 'recording' }, record, ' ', recordingText));
  root.append(el('div', { class: 'status' },
    el('section', {}, el('h3', {}, 'Session'), summary),
    el('section', {}, el('h3', {}, 'Timing per component'), timings)),
  el('section', {}, el('h3', {}, 'Faults and events'), log));
  let last = 0;
  // A restarted server numbers its events from 1 again: the old run's go, and the log is read again from the start.
  // An answer asked for before the restart is dropped (run counts the restarts).
  let run = 0;
  const leaveRestart = onRestart(() => {
    run += 1;
    last = 0;
    log.replaceChildren();
  });

  async function refresh(): Promise<void> {
    const [{ status: s }, surgeon] = await Promise.all([api<StatusReply>('GET', '/status'), api<SurgeonView>('GET', '/surgeon')]);
    const rows: [string, string][] = [
      ['robot', `${s.robot} (${s.graph})`], ['transport', s.transport], ['modules', `${s.modulesFound} of ${s.modulesConfigured} found`],
      ['run level', s.robotState], ['robot layer', s.robotLayer], ['session', s.session], ['torque', s.torqueOn ? 'on' : 'off'], ['loop rate', `${s.loopRateHz} Hz`],
      ['ticks', String(s.ticks)], ['session time', `${fmt(s.sessionSeconds, 1)} s`],
      ['tick time', `median ${fmt(s.tickMedianUs, 1)} µs, p99 ${fmt(s.tickP99Us, 1)} µs, max ${fmt(s.tickMaxUs, 1)} µs`],
      ['deadline misses', String(s.deadlineMisses)],
      ['allocated in ticks', s.tickAllocatedBytes === null ? 'not counted (real bus)' : `${s.tickAllocatedBytes} B in ${s.ticks} ticks`], ['faults', faultWords(s, surgeon).join('; ') || 'none'], ['plug-in faults', String(s.pluginFaults)],
      ['bus', `${s.bus.cycles} cycles, ${s.bus.frames} frames, ${s.bus.crcErrors} CRC errors, ${s.bus.timeouts} timeouts, ${s.bus.retries} retries`],
    ];
    summary.replaceChildren(...rows.map(([k, v]) => el('tr', {}, el('th', {}, k), el('td', {}, v))));
    markFirstValue(root);
    const t = await api<Timing[]>('GET', '/timings');
    timings.replaceChildren(el('tr', {}, ...['component', 'runs', 'median µs', 'p99 µs', 'max µs'].map((h) => el('th', {}, h))),
      ...t.map((x) => el('tr', {}, el('td', {}, x.component), el('td', {}, String(x.count)), el('td', {}, fmt(x.medianUs, 1)), el('td', {}, fmt(x.p99Us, 1)), el('td', {}, fmt(x.maxUs, 1)))));
    const asked = run;
    const events = await api<EventEntry[]>('GET', `/events?after=${last}`);
    if (asked !== run) return;
    for (const e of events) {
      if (e.sequence <= last) continue; // already shown: an answer to a refresh that overlapped this one
      last = e.sequence;
      log.prepend(el('tr', {}, el('td', {}, `${fmt(e.timeSeconds, 3)} s`), el('td', {}, e.source), el('td', {}, e.message)));
    }
  }

  const timer = setInterval(() => void refresh().then(refreshRecording).catch(() => undefined), 500);
  void refresh().then(refreshRecording).catch(() => undefined);
  return () => { clearInterval(timer); leaveRestart(); };
}
