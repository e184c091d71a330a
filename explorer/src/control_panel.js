// The inputs: a slider and an exact number box per numeric config key (an on/off box for the
// optional ones), a select per closed choice, the value's readout in the other unit system, and
// a line under each control for the core's message when that key is at fault.
import { CONTROLS } from './controls.js';
import { shown, switchUnits, listOf } from './state.js';
import { scales, toSI, fromSI, converts, SI_UNIT, short } from './units.js';

const GROUP_TITLES = { run: 'run', scales: 'SI scales', profile: 'table motion', law: 'friction law', table: 'table friction' };

// The slider's range in the state's units: the [-] range times the scale in SI runs.
function sliderRange(c, s) {
  if (s.units !== 'si' || !converts(c.dim)) return c.range;
  const k = scales(s)[c.dim];
  return [c.range[0] * k, c.range[1] * k];
}

export class ControlPanel {
  // onChange(key) after the state changed through a control.
  constructor(root, state, onChange) {
    this.root = root;
    this.state = state;
    this.onChange = onChange;
    this.rows = {};
    const groups = {};
    for (const c of CONTROLS) {
      if (!groups[c.group]) {
        const fs = document.createElement('fieldset');
        fs.innerHTML = `<legend>${GROUP_TITLES[c.group]}</legend>`;
        root.appendChild(fs);
        groups[c.group] = fs;
      }
      groups[c.group].appendChild(this.row(c));
    }
    this.refresh();
  }

  row(c) {
    const div = document.createElement('div');
    div.className = 'control';
    div.dataset.key = c.key;
    const optional = c.optional ? '<input type="checkbox" class="enable" title="on: set this key; off: none (the CLI default)">' : '';
    if (c.kind === 'list') {
      div.innerHTML = `<label>${c.label}</label><input type="text" class="value list" spellcheck="false"><span class="unit"></span><span class="other"></span><div class="control-error"></div>`;
      const box = div.querySelector('.value');
      box.addEventListener('input', () => {
        if (listOf(box.value).every(Number.isFinite)) this.set(c, box.value.trim(), { keepBox: true });
      });
    } else if (c.kind === 'select') {
      div.innerHTML = `<label>${c.label}</label><select class="value">${c.options.map((o) => `<option>${o}</option>`).join('')}</select><div class="control-error"></div>`;
      div.querySelector('select').addEventListener('change', (e) => this.set(c, e.target.value));
    } else {
      div.innerHTML = `<label>${optional}${c.label}</label><input type="range" class="slider"><input type="number" class="value" step="any"><span class="unit"></span>` +
        (c.key === 'period' ? '<span class="si-only">f <input type="number" class="frequency" step="any"> Hz</span>' : '') +
        '<span class="other"></span><div class="control-error"></div>';
      const slider = div.querySelector('.slider'), box = div.querySelector('.value');
      slider.addEventListener('input', () => {
        let v = Number(slider.value);
        if (c.log) v = Number((10 ** v).toPrecision(6));
        if (c.integer) v = Math.round(v);
        box.value = String(v);
        this.set(c, v);
      });
      box.addEventListener('input', () => {
        const v = Number(box.value);
        if (box.value.trim() !== '' && Number.isFinite(v)) this.set(c, v, { keepBox: true });
      });
      const en = div.querySelector('.enable');
      if (en) en.addEventListener('change', () => { this.state.enabled[c.key] = en.checked; this.changed(c.key); });
      const f = div.querySelector('.frequency');
      if (f) f.addEventListener('input', () => {
        const v = Number(f.value);
        if (v > 0) this.set(c, 1 / v, { keepFrequency: true });
      });
    }
    this.rows[c.key] = div;
    return div;
  }

  set(c, value, how = {}) {
    // A change of units keeps the physical setting: every dimensional value is converted.
    if (c.key === 'units') Object.assign(this.state, switchUnits(this.state, value));
    else this.state[c.key] = value;
    this.changed(c.key, how);
  }

  changed(key, how = {}) {
    this.refresh(how);
    this.onChange(key);
  }

  // Shows the state: visibility, values, slider positions and ranges, the other system's values.
  refresh(how = {}) {
    const s = this.state;
    const si = s.units === 'si';
    const sc = scales(s);
    this.root.classList.toggle('si', si);
    for (const c of CONTROLS) {
      const div = this.rows[c.key];
      div.hidden = !shown(c, s);
      const box = div.querySelector('.value');
      if (c.kind === 'select') { box.value = s[c.key]; continue; }
      if (c.kind === 'list') {
        if (!how.keepBox || document.activeElement !== box) box.value = s[c.key];
        div.querySelector('.unit').textContent = si ? SI_UNIT[c.dim] : '[-]';
        const values = listOf(s[c.key]);
        div.querySelector('.other').textContent = '≙ ' + values.map((v) => short(si ? fromSI(c.dim, v, sc) : toSI(c.dim, v, sc))).join(', ') + (si ? ' [-]' : ` ${SI_UNIT[c.dim]}`);
        continue;
      }
      if (!how.keepBox || document.activeElement !== box) box.value = String(s[c.key]);
      const en = div.querySelector('.enable');
      const on = !c.optional || s.enabled[c.key];
      if (en) en.checked = on;
      div.classList.toggle('off', !on);
      const [lo, hi] = sliderRange(c, s);
      const slider = div.querySelector('.slider');
      if (c.log) {
        slider.min = Math.log10(lo); slider.max = Math.log10(hi); slider.step = 'any';
        slider.value = Math.log10(s[c.key]);
      } else {
        slider.min = lo; slider.max = hi; slider.step = c.integer ? 1 : 'any';
        slider.value = s[c.key];
      }
      const unit = c.unit ?? (converts(c.dim) ? (si ? SI_UNIT[c.dim] : '[-]') : '[-]');
      div.querySelector('.unit').textContent = unit;
      const other = div.querySelector('.other');
      if (converts(c.dim)) {
        other.textContent = si ? `≙ ${short(fromSI(c.dim, s[c.key], sc))} [-]` : `≙ ${short(toSI(c.dim, s[c.key], sc))} ${SI_UNIT[c.dim]}`;
      } else {
        other.textContent = '';
      }
      const f = div.querySelector('.frequency');
      if (f && !how.keepFrequency) f.value = String(Number((1 / s.period).toPrecision(12)));
    }
  }

  // The core's message under each control it names (and under `blame`, the control just moved).
  showError(message, keys, blame) {
    this.clearErrors();
    const all = new Set(keys);
    if (blame) all.add(blame);
    let placed = false;
    // a config key names its controls (both families' `accelerations`: the one shown)
    for (const c of CONTROLS) if (c.configKey && all.has(c.configKey)) all.add(c.key);
    for (const k of all) {
      const div = this.rows[k];
      if (!div || div.hidden) continue;
      div.querySelector('.control-error').textContent = message;
      div.classList.add('at-fault');
      placed = true;
    }
    return placed;
  }

  clearErrors() {
    for (const div of Object.values(this.rows)) {
      div.querySelector('.control-error').textContent = '';
      div.classList.remove('at-fault');
    }
  }
}
