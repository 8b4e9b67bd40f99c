// New run: pick a preset (the paper's six assemblies and their -quick variants, ...), edit
// the key parameters or the whole scene JSON, submit. An unchanged preset is sent as
// {"preset": NAME} so the run keeps its preset's name; an edited one as the whole scene.
// The API's validation errors appear beside the field they name.
// #/new?from=ID is a new test on run ID's specimen: its scene with "start_from": {"run_id": ID,
// "stage": S} (S one of the stages whose end the run kept; by default the one before the first
// shearing stage), so only the stages after S run; the specimen's own settings are not shown.
import { api } from '../api.js';
import { h, replaceChildren } from '../dom.js';
import {
  SCENE_FIELDS, applyValue, describeScene, displayValue, fieldForPath, fieldVisible, useShapeFidelityTable,
} from '../scene_form.js';

const DEFAULT_PRESET = 'circular-quick';
const SHEARING = ['biaxial', 'rotation', 'cyclic', 'simple_shear'];

export function newRunView(root, params) {
  const presetSelect = h('select', { id: 'preset', 'aria-label': 'Preset', onchange: () => loadPreset(presetSelect.value) });
  const description = h('div', { class: 'hint' });
  const grid = h('div', { class: 'form-grid' });
  const formError = h('div', { class: 'form-error', hidden: true });
  const submit = h('button', { type: 'submit', class: 'primary' }, 'Start run');
  const jsonBox = h('textarea', { class: 'scene-json', spellcheck: 'false', 'aria-label': 'Scene JSON', oninput: () => jsonEdited() });
  const jsonError = h('div', { class: 'field-error' });
  const jsonDetails = h('details', { open: true }, h('summary', {}, 'Scene JSON (every parameter; edits here update the form)'), jsonBox, jsonError);
  const fromId = params.has('from') ? Number(params.get('from')) : null;
  const specimenStage = h('select', { id: 'specimen-stage', 'aria-label': 'Start after stage', onchange: () => setSpecimenStage(specimenStage.value) });
  const specimenText = h('span');
  const form = h('form', { class: 'panel', novalidate: true, onsubmit: (event) => { event.preventDefault(); start(); } },
    h('div', { class: 'form-grid' },
      fromId === null ? h('label', { for: 'preset' }, 'Preset') : h('label', { for: 'specimen-stage' }, 'Specimen'),
      fromId === null
        ? h('div', { class: 'field-input' }, presetSelect, description)
        : h('div', { class: 'field-input specimen' }, specimenText, specimenStage,
          h('div', { class: 'hint' }, 'the stages up to this one are the specimen\'s; the later ones run on it. ',
            h('a', { href: '#/new' }, 'Start from a preset instead')), description)),
    grid,
    h('div', { class: 'form-actions' }, submit, h('span', { class: 'hint' }, 'Quick presets finish in seconds; the full ones take much longer.')),
    formError);
  replaceChildren(root,
    h('div', { class: 'view-title' }, h('h2', {}, fromId === null ? 'New run' : `New test on run #${fromId}'s specimen`)),
    h('div', { class: 'new-run' }, form, h('div', { class: 'panel' }, jsonDetails)));

  let presetName = null;
  let presetJson = '';   // the preset's scene as loaded, to tell whether it was edited
  let scene = null;
  const inputs = new Map();  // field key → {row, input, error}
  let destroyed = false;

  function buildFields() {
    const children = [];
    for (const field of SCENE_FIELDS) {
      if (field.section) {
        children.push(h('div', { class: 'form-section', dataset: { section: field.section } }, field.section));
        continue;
      }
      const id = `field-${field.key}`;
      const input = field.kind === 'select'
        ? h('select', { id, name: field.key }, field.options.map(([value, text]) => h('option', { value }, text)))
        : h('input', {
          id, name: field.key, type: 'text', autocomplete: 'off',
          inputmode: field.kind === 'text' ? null : 'decimal', placeholder: 'default',
        });
      input.addEventListener(field.kind === 'select' ? 'change' : 'input', () => fieldEdited(field));
      const error = h('div', { class: 'field-error', dataset: { errorFor: field.key } });
      // A field with measured figures (shape fidelity) shows them under its hint.
      const figures = field.figures ? h('div', { class: 'hint figures', dataset: { figuresFor: field.key } }) : null;
      const box = h('div', { class: 'field-input' }, input, field.hint ? h('div', { class: 'hint' }, field.hint) : null, figures, error);
      const label = h('label', { for: id }, field.label, field.unit ? h('span', { class: 'unit' }, ` (${field.unit})`) : null);
      inputs.set(field.key, { label, box, input, error, figures });
      children.push(label, box);
    }
    replaceChildren(grid, children);
  }

  // On a prepared specimen its particles, material and engine are set: the server refuses a
  // scene that differs from them (start_from.run_id).
  const specimenKeys = new Set(['seed', 'engine']);
  let section = null;
  for (const field of SCENE_FIELDS) {
    if (field.section) section = field.section;
    else if (section === 'Material' || section === 'Specimen') specimenKeys.add(field.key);
  }
  const shown = (field) => fieldVisible(field, scene) && !(fromId !== null && specimenKeys.has(field.key));

  /** Shows the scene's values; hides the fields the scene has no place for. */
  function fillForm() {
    description.textContent = describeScene(scene);
    for (const field of SCENE_FIELDS) {
      if (field.section) continue;
      const { label, box, input } = inputs.get(field.key);
      const visible = shown(field);
      label.hidden = !visible;
      box.hidden = !visible;
      if (visible && document.activeElement !== input) input.value = displayValue(field, scene);
      if (field.figures) showFigures(inputs.get(field.key).figures, visible ? field.figures(scene) : null);
    }
    for (const section of grid.querySelectorAll('.form-section')) {
      const fields = SCENE_FIELDS.slice(SCENE_FIELDS.findIndex((f) => f.section === section.dataset.section) + 1);
      const end = fields.findIndex((f) => f.section);
      section.hidden = !(end < 0 ? fields : fields.slice(0, end)).some(shown);
    }
  }

  function showFigures(box, figures) {
    box.hidden = !figures;
    if (!figures) return;
    replaceChildren(box, h('div', {}, figures.heading), ...figures.rows.map(({ quantity, label, text }) =>
      h('div', { dataset: { quantity } }, `${label}: `, h('span', { class: 'figure' }, text))));
  }

  function showJson() {
    jsonBox.value = JSON.stringify(scene, null, 2);
    jsonBox.classList.remove('invalid');
    jsonError.textContent = '';
  }

  function clearErrors() {
    formError.hidden = true;
    for (const { box, error } of inputs.values()) {
      box.classList.remove('invalid');
      error.textContent = '';
    }
  }

  function showFieldError(field, message) {
    const { box, error, input } = inputs.get(field.key);
    box.classList.add('invalid');
    error.textContent = message;
    input.focus();
  }

  function fieldEdited(field) {
    if (!scene) return;
    const { box, error, input } = inputs.get(field.key);
    const problem = applyValue(field, scene, input.value);
    box.classList.toggle('invalid', Boolean(problem));
    error.textContent = problem ?? '';
    fillForm();
    showJson();
  }

  function jsonEdited() {
    try {
      const parsed = JSON.parse(jsonBox.value);
      if (parsed === null || typeof parsed !== 'object' || Array.isArray(parsed)) throw new Error('the scene must be a JSON object');
      scene = parsed;
      jsonBox.classList.remove('invalid');
      jsonError.textContent = '';
      clearErrors();
      fillForm();
    } catch (error) {
      jsonBox.classList.add('invalid');
      jsonError.textContent = `Not a valid scene yet: ${error.message}`;
    }
  }

  async function loadPreset(name) {
    try {
      const loaded = await api.preset(name);
      if (destroyed) return;
      presetName = name;
      presetJson = JSON.stringify(loaded);
      scene = loaded;
      clearErrors();
      fillForm();
      showJson();
    } catch (error) {
      formError.hidden = false;
      formError.textContent = `Cannot load preset ${name}: ${error.message}`;
    }
  }

  /** run `fromId`'s scene, to start from the end of one of the stages whose end it kept. */
  async function loadSpecimen() {
    try {
      const parent = await api.run(fromId);
      if (destroyed) return;
      const stages = parent.scene?.stages ?? [];
      // The parser names an unnamed stage by its type (free by default).
      const nameOf = (stage) => stage.name ?? stage.type ?? 'free';
      // A stage with a later stage to run after it.
      const kept = (parent.specimen_stages ?? []).filter((name) => {
        const k = stages.findIndex((stage) => nameOf(stage) === name);
        return k >= 0 && k + 1 < stages.length;
      });
      if (!kept.length) throw new Error(`run #${fromId} kept no stage's end to start from`);
      const firstShearing = stages.findIndex((stage, k) => k > 0 && SHEARING.includes(stage.type));
      const preparation = firstShearing > 0 ? nameOf(stages[firstShearing - 1]) : null;
      specimenText.textContent = `run #${fromId} ${parent.name} (${parent.particles} particles), at the end of stage`;
      replaceChildren(specimenStage, kept.map((name) => h('option', { value: name }, name)));
      specimenStage.value = kept.includes(preparation) ? preparation : kept[kept.length - 1];
      scene = structuredClone(parent.scene);
      presetJson = '';
      setSpecimenStage(specimenStage.value);
    } catch (error) {
      formError.hidden = false;
      formError.textContent = `Cannot start from run #${fromId}: ${error.message}`;
    }
  }

  function setSpecimenStage(stage) {
    if (!scene) return;
    scene.start_from = { run_id: fromId, stage };
    clearErrors();
    fillForm();
    showJson();
  }

  async function start() {
    if (!scene) return;
    if (jsonBox.classList.contains('invalid')) {
      jsonDetails.open = true;
      formError.hidden = false;
      formError.textContent = 'The scene JSON is not valid: fix it or pick the preset again.';
      return;
    }
    const localProblem = [...inputs.values()].find(({ box }) => box.classList.contains('invalid'));
    if (localProblem) {
      localProblem.input.focus();
      return;
    }
    clearErrors();
    submit.disabled = true;
    const edited = JSON.stringify(scene) !== presetJson;
    try {
      const id = await api.createRun(edited ? scene : { preset: presetName });
      location.hash = `#/run/${id}`;
    } catch (error) {
      const field = fieldForPath(scene, error.field);
      if (field && fieldVisible(field, scene)) {
        showFieldError(field, error.message);
      } else {
        formError.hidden = false;
        formError.textContent = error.field ? `${error.field}: ${error.message}` : error.message;
        if (error.field) jsonDetails.open = true;
      }
    } finally {
      submit.disabled = false;
    }
  }

  buildFields();
  // The measured shape-fidelity table (a static file): the form works without it.
  fetch('tables/shape-fidelity.json').then((r) => (r.ok ? r.json() : null)).then((table) => {
    if (destroyed || !table) return;
    useShapeFidelityTable(table);
    if (scene) fillForm();
  }).catch(() => {});
  if (fromId !== null) loadSpecimen();
  else (async () => {
    try {
      const presets = await api.presets();
      if (destroyed) return;
      replaceChildren(presetSelect, presets.map((name) => h('option', { value: name }, name)));
      const wanted = params.get('preset');
      presetSelect.value = presets.includes(wanted) ? wanted : presets.includes(DEFAULT_PRESET) ? DEFAULT_PRESET : presets[0];
      await loadPreset(presetSelect.value);
    } catch (error) {
      formError.hidden = false;
      formError.textContent = `Cannot list the presets: ${error.message}`;
    }
  })();

  return {
    destroy() {
      destroyed = true;
    },
  };
}
