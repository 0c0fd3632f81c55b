// Unsaved edits kept in this browser (localStorage), so that leaving the page, a reload or a server restart loses
// nothing: the edited graph with its undo and redo steps, the file name, and the file as it was last loaded or saved
// (what "unsaved" is measured against). A graph with problems is kept too: the server refuses to save it, the draft
// does not.
import type { HistoryState } from './model';

export interface Draft { fileName: string; baseline: string; loadedName: string; history: HistoryState; at: number }

const key = 'rc-editor-draft';
const maxSteps = 200; // undo steps kept with a draft (the oldest go first)

export function readDraft(): Draft | null {
  try {
    const text = localStorage.getItem(key);
    const d = text === null ? null : (JSON.parse(text) as Draft);
    return d && typeof d.fileName === 'string' && d.history?.graph ? d : null;
  } catch {
    return null; // a draft this version cannot read is no draft
  }
}

export function writeDraft(d: Draft): void {
  const history = { ...d.history, undos: d.history.undos.slice(-maxSteps), redos: d.history.redos.slice(-maxSteps) };
  try {
    localStorage.setItem(key, JSON.stringify({ ...d, history }));
  } catch {
    localStorage.setItem(key, JSON.stringify({ ...d, history: { ...history, undos: [], redos: [] } })); // full: keep the graph at least
  }
}

export function clearDraft(): void {
  localStorage.removeItem(key);
}
