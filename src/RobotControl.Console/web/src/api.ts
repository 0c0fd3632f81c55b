// The console's JSON API (docs/console.md). Every request names this page with X-Console-Client, so the server
// can tell the operator's console from the watchers'.
const clientKey = 'rc-console-client';
export const clientId: string = sessionStorage.getItem(clientKey) ?? (() => {
  const id = crypto.randomUUID();
  sessionStorage.setItem(clientKey, id);
  return id;
})();

// The session's access token: the console prints its URL with ?token=...; the page keeps it in this tab's
// sessionStorage, takes it out of the address bar (and so out of history and bookmarks) and sends it with every API
// call (Authorization: Bearer) and WebSocket (?token=). Without it the API answers 401; E-STOP still works.
const tokenKey = 'rc-console-token';
export const token: string | null = (() => {
  const url = new URL(location.href);
  const given = url.searchParams.get('token');
  if (given) {
    sessionStorage.setItem(tokenKey, given);
    url.searchParams.delete('token');
    history.replaceState(history.state, '', `${url.pathname}${url.search}${url.hash}`);
  }
  return sessionStorage.getItem(tokenKey);
})();

export class ApiError extends Error {
  constructor(readonly status: number, message: string, readonly details: string[] = []) {
    super(message);
  }
}

// Whether the server answered the last request: a fetch that fails (no answer at all) tells the status bar at once,
// and so does the next answer.
const reachListeners: ((reached: boolean) => void)[] = [];
export function onReach(listener: (reached: boolean) => void): void {
  reachListeners.push(listener);
}
export function reached(yes: boolean): void {
  for (const l of reachListeners) l(yes);
}

// The console server's run (docs/console.md, "After a restart"): every API answer names it (X-Console-Instance) and so
// does the stream's answer to a subscription. When it changes the server was restarted: whatever a page holds from the
// old run (samples, events, values) is the old run's, so every page that keeps any starts again from here.
let instance: string | null = null;
const restartListeners = new Set<() => void>();

/** Calls <listener> each time the page sees a new run of the console server; returns the unsubscribe. */
export function onRestart(listener: () => void): () => void {
  restartListeners.add(listener);
  return () => restartListeners.delete(listener);
}

/** The one place a server run is compared: the first one seen is kept; a different one restarts every page. */
export function noticeInstance(seen: string | null): void {
  if (!seen || seen === instance) return;
  const restarted = instance !== null;
  instance = seen;
  if (restarted) for (const l of [...restartListeners]) l();
}

/** The page's first useful value (the start-up measurement, docs/performance.md): the time since navigation, once per visit. */
export function markFirstValue(root: HTMLElement): void {
  if (root.dataset.firstValue !== undefined) return;
  root.dataset.firstValue = performance.now().toFixed(1);
  performance.mark('first-value', { detail: root.dataset.page });
}

export async function api<T>(method: string, path: string, body?: unknown): Promise<T> {
  let response: Response;
  try {
    response = await fetch(`/api${path}`, {
      method,
      headers: { 'X-Console-Client': clientId, ...(token ? { Authorization: `Bearer ${token}` } : {}), ...(body === undefined ? {} : { 'Content-Type': 'application/json' }) },
      body: body === undefined ? undefined : JSON.stringify(body),
    });
  } catch (e) {
    reached(false);
    throw new ApiError(0, `${method} /api${path}: the console server cannot be reached (${(e as Error).message})`);
  }
  reached(true);
  noticeInstance(response.headers.get('X-Console-Instance'));
  const text = await response.text();
  const data = text.length > 0 ? JSON.parse(text) : {};
  if (!response.ok) {
    throw new ApiError(response.status, data.error ?? `${response.status} ${response.statusText}`, data.details ?? []);
  }
  return data as T;
}

/** The message line under the status bar: a refusal or failure is a full-width banner (role=alert) with the server's line. */
export function show(message: string, error = false): void {
  const box = document.getElementById('message')!;
  box.textContent = message;
  box.className = error ? 'error' : 'ok';
  box.setAttribute('role', error ? 'alert' : 'status');
}

/** Runs an action, showing its result line (or the server's error) in the message bar. */
export async function act(run: () => Promise<{ message: string; details?: string[] }>): Promise<boolean> {
  try {
    const result = await run();
    show([result.message, ...(result.details ?? [])].join('\n'));
    return true;
  } catch (e) {
    const err = e as ApiError;
    show([err.message, ...(err.details ?? [])].join('\n'), true);
    return false;
  }
}

export interface ParameterSpec { key: string; label: string; unit: string; value: number | string; fileValue: number; min: number; max: number }
export interface MotorView {
  name: string; joint: string; channel: number; positionDeg: number; minDeg: number; maxDeg: number; currentA: number; pwm: number;
  manual: boolean; torqueOn: boolean; errors: string[]; parameters: ParameterSpec[];
  /** The goal it follows (jog or setpoint target in manual, else the loop's), the loop's goal (where a release sends it), its speed limit. */
  desiredDeg: number; loopCommandDeg: number; speedLimitDegS: number;
  /** Ring signals (radians) of its desired and measured axis output. */
  desiredSignal: string; measuredSignal: string;
}
export interface ControllerView {
  id: number; name: string; present: boolean; missedReplies: number; model: number; firmware: number; resetCause: string; resets: number; watchdog: string;
  hardwareErrors: string[]; motors: MotorView[];
}
export interface SessionStatus {
  robot: string; graph: string; transport: string; modulesConfigured: number; modulesFound: number; loopRateHz: number; ticks: number;
  deadlineMisses: number; tickMedianUs: number; tickP99Us: number; tickMaxUs: number; tickAllocatedBytes: number | null; sessionSeconds: number; robotState: string;
  robotLayer: string; session: string;
  torqueOn: boolean; faults: string[]; pluginFaults: number;
  bus: { cycles: number; frames: number; crcErrors: number; timeouts: number; retries: number };
}
export interface StatusReply { status: SessionStatus; operator: { held: boolean; you: boolean }; instance: string }
export interface ArmView { name: string; joints: string[]; positionSignals: string[]; commandSignals: string[] }
export interface RobotModel { urdf: string; arms: ArmView[] }
