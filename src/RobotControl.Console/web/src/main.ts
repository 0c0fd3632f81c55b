import './style.css';
import { busPage } from './pages/bus';
import { replayBar } from './replay';
import { statusBar } from './statusbar';

/** A page: renders into its element, and stops its timers and sockets when left. */
export type Page = (root: HTMLElement) => () => void;

// The bus page ships in the main chunk; the others load on first visit (three.js and uPlot are most of the bundle).
const pages: Record<string, () => Promise<Page>> = {
  bus: () => Promise.resolve(busPage),
  plots: async () => (await import('./pages/plots')).plotsPage,
  tune: async () => (await import('./pages/tune')).tunePage,
  view3d: async () => (await import('./pages/view3d')).view3dPage,
  status: async () => (await import('./pages/status')).statusPage,
  editor: async () => (await import('./pages/editor/page')).editorPage,
  surgeon: async () => (await import('./pages/surgeon')).surgeonPage,
  bringup: async () => (await import('./pages/bringup')).bringupPage,
};
let leave: (() => void) | null = null;
let visit = 0;

async function route(): Promise<void> {
  const name = location.hash.replace('#', '') || 'bus';
  const load = pages[name] ?? pages.bus;
  const current = ++visit;
  leave?.();
  leave = null;
  const root = document.getElementById('page')!;
  root.replaceChildren();
  root.dataset.page = name;
  delete root.dataset.firstValue; // the start-up measurement: each visit marks its own first value
  document.querySelectorAll<HTMLAnchorElement>('nav a').forEach((a) => a.classList.toggle('active', a.dataset.page === name));
  const page = await load();
  if (current === visit) leave = page(root);
}

window.addEventListener('hashchange', () => void route());
statusBar(document.getElementById('statusbar')!, document.getElementById('unreachable')!);
void route();
void replayBar(document.getElementById('replay')!);
