// What every view of the page does alike: its numbers, and the core's message over the last
// good plot (dimmed, never blank; numbers "—", never NaN).
export class View {
  constructor(root) {
    this.root = root;
  }

  // Shows `text` in the view's [data-number=name] cell.
  setNumber(name, text) {
    this.root.querySelector(`[data-number="${name}"]`).textContent = text;
  }

  // The view's unit labels ([data-unit=dimension]) from `unitLabel(dimension)`.
  setUnits(unitLabel) {
    for (const el of this.root.querySelectorAll('[data-unit]')) el.textContent = unitLabel(el.dataset.unit);
  }

  solved() { this.root.classList.remove('stale'); }

  fail(message) {
    this.root.classList.add('stale');
    for (const el of this.root.querySelectorAll('[data-number]')) el.textContent = '—';
    this.root.querySelector('.view-error').textContent = message;
  }

  clearError() { this.root.querySelector('.view-error').textContent = ''; }
}
