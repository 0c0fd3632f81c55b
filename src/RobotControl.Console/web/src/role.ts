// The operator role as the page shows it. Controls that need the role carry data-operator; while this console only
// watches (or another console holds the role) they are disabled, aria-disabled and say why. Stop and E-STOP never
// carry it. Controls a page adds later (its cards, its rows) are caught as they are added.

/** operator: this console holds the role; held: another console does; watching: nobody does. */
export type RoleState = 'operator' | 'held' | 'watching';

const why: Record<RoleState, string> = {
  operator: '',
  held: 'another console holds the operator role: this one watches',
  watching: 'this needs the operator role: take it in the status bar',
};

function apply(state: RoleState, scope: ParentNode): void {
  const can = state === 'operator';
  for (const c of scope.querySelectorAll<HTMLButtonElement | HTMLInputElement>('[data-operator]')) {
    if (can && c.dataset.roleDisabled !== undefined) {
      c.disabled = false;
      delete c.dataset.roleDisabled;
      c.removeAttribute('aria-disabled');
      c.removeAttribute('title');
    } else if (!can && !c.disabled) {
      c.disabled = true;
      c.dataset.roleDisabled = '';
      c.setAttribute('aria-disabled', 'true');
      c.title = why[state];
    }
  }
}

/** Watches <paramref name="page"/> and the bar; returns the function the bar calls with each role state it reads. */
export function watchRole(page: HTMLElement): (state: RoleState) => void {
  let current: RoleState = 'watching';
  new MutationObserver((changes) => {
    if (current !== 'operator' && changes.some((c) => c.addedNodes.length > 0)) apply(current, page);
  }).observe(page, { childList: true, subtree: true });
  return (state) => {
    current = state;
    document.body.dataset.role = state;
    apply(state, document);
  };
}
