import { el } from '../dom';

// The endoscope video: any capture device the browser sees (a V4L2/UVC device such as an HDMI/SDI capture card),
// chosen in a picker; the choice is remembered in this browser (localStorage).
const storageKey = 'rc-endoscope-device';

export function videoPanel(): { element: HTMLElement; stop: () => void } {
  const video = el('video', { 'data-testid': 'endoscope', autoplay: '', muted: '', playsinline: '' });
  video.muted = true;
  const picker = el('select', { 'data-testid': 'video-device', 'aria-label': 'video source' });
  const note = el('div', { class: 'video-note', 'data-testid': 'video-note' });
  const element = el('section', { class: 'video' }, video, el('div', { class: 'video-bar' }, el('span', {}, 'Endoscope'), picker), note);
  let stream: MediaStream | null = null;
  let stopped = false;

  const stopStream = () => { stream?.getTracks().forEach((t) => t.stop()); stream = null; };

  async function listDevices(current: string | undefined): Promise<void> {
    const devices = (await navigator.mediaDevices.enumerateDevices()).filter((d) => d.kind === 'videoinput');
    picker.replaceChildren(...devices.map((d, i) => el('option', { value: d.deviceId }, d.label || `camera ${i + 1}`)));
    if (current) picker.value = current;
  }

  async function open(deviceId: string | null): Promise<void> {
    stopStream();
    note.textContent = '';
    if (!navigator.mediaDevices?.getUserMedia) {
      note.textContent = 'No video: this browser gives no camera access on this address (use https or open the console on the same machine).';
      return;
    }
    try {
      const s = await navigator.mediaDevices.getUserMedia({ video: deviceId ? { deviceId: { exact: deviceId } } : true, audio: false });
      if (stopped) { s.getTracks().forEach((t) => t.stop()); return; }
      stream = s;
      video.srcObject = s;
      const id = s.getVideoTracks()[0]?.getSettings().deviceId;
      if (id) localStorage.setItem(storageKey, id);
      await listDevices(id);
    } catch (e) {
      const name = (e as DOMException).name;
      if (deviceId && (name === 'NotFoundError' || name === 'OverconstrainedError')) {
        note.textContent = 'The remembered video source is not connected; showing the default one.';
        localStorage.removeItem(storageKey);
        await open(null);
        note.textContent = stream ? 'The remembered video source is not connected; showing the default one.' : note.textContent;
        return;
      }
      note.textContent = name === 'NotAllowedError' || name === 'SecurityError'
        ? 'No video: camera access was denied. Allow video capture for this page in the browser, then reload.'
        : name === 'NotFoundError' || name === 'OverconstrainedError'
          ? 'No video: no capture device found. Connect the endoscope\'s capture card.'
          : `No video: ${(e as Error).message}`;
    }
  }

  picker.addEventListener('change', () => void open(picker.value));
  void open(localStorage.getItem(storageKey));
  return { element, stop: () => { stopped = true; stopStream(); } };
}
