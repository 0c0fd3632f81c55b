import './style.css';
import { api, act, show, type StatusReply } from './api';
import { busPage } from './pages/bus';
import { plotsPage } from './pages/plots';
import { view3dPage } from './pages/view3d';
import { statusPage } from './pages/status';

/** A page: renders into its element, and stops its timers and sockets when left. */
export type Page = (root: HTMLElement) => () => void;

const pages: Record<string, Page> = { bus: busPage, plots: plotsPage, view3d: view3dPage, status: statusPage };
let leave: (() => void) | null = null;

function route(): void {
  const name = location.hash.replace('#', '') || 'bus';
  const page = pages[name] ?? busPage;
  leave?.();
  const root = document.getElementById('page')!;
  root.replaceChildren();
  root.dataset.page = name;
  document.querySelectorAll<HTMLAnchorElement>('nav a').forEach((a) => a.classList.toggle('active', a.dataset.page === name));
  leave = page(root);
}

async function heartbeat(): Promise<void> {
  try {
    const reply = await api<StatusReply>('GET', '/status');
    document.getElementById('robot')!.textContent = `${reply.status.robot} · ${reply.status.transport}`;
    const role = document.getElementById('role')!;
    role.textContent = reply.operator.you ? 'operator' : reply.operator.held ? 'watching (another console operates)' : 'watching';
    role.dataset.role = reply.operator.you ? 'operator' : 'watcher';
    document.getElementById('claim')!.hidden = reply.operator.you;
  } catch (e) {
    show((e as Error).message, true);
  }
}

document.getElementById('claim')!.addEventListener('click', () =>
  act(async () => {
    await api('POST', '/operator');
    await heartbeat();
    return { message: 'this console is the operator' };
  }));
window.addEventListener('hashchange', route);
route();
void heartbeat();
setInterval(() => void heartbeat(), 1000);
