// The program editor: CodeMirror 6 with the Fanuc / Macro B mode, the run's alarms and
// warnings as diagnostics (gutter markers, wavy underlines, hover text, F8 to the next one),
// search (Ctrl+F), go to line (Ctrl+Alt+G or the button), and the block of the timeline's
// current step highlighted. CodeMirror draws only the lines in view, so a keystroke costs the
// same in a million-line program as in ten lines. Lines are 1-based, as in the trace.
import { EditorState, StateEffect, StateField, RangeSet } from '@codemirror/state';
import {
  EditorView, Decoration, GutterMarker, gutterLineClass, keymap, lineNumbers, highlightActiveLine,
  highlightActiveLineGutter, highlightSpecialChars, drawSelection, rectangularSelection,
} from '@codemirror/view';
import { defaultKeymap, history, historyKeymap, indentWithTab } from '@codemirror/commands';
import { searchKeymap, highlightSelectionMatches, openSearchPanel, gotoLine } from '@codemirror/search';
import { lintGutter, setDiagnostics, forEachDiagnostic, lintKeymap } from '@codemirror/lint';
import { fanuc } from './fanuc-mode.js';

// The timeline's current block: a position (a line start), mapped through edits.
const setCurrentBlock = StateEffect.define();
const currentBlock = StateField.define({
  create: () => -1,
  update(pos, tr) {
    for (const e of tr.effects) if (e.is(setCurrentBlock)) return e.value;
    return pos >= 0 && tr.docChanged ? tr.changes.mapPos(pos, -1) : pos;
  },
});
const currentGutter = new (class extends GutterMarker {
  elementClass = 'cm-current-block-gutter';
})();
const currentDecorations = [
  EditorView.decorations.compute([currentBlock], (state) => {
    const pos = state.field(currentBlock);
    if (pos < 0 || pos > state.doc.length) return Decoration.none;
    const line = state.doc.lineAt(pos);
    return Decoration.set([
      Decoration.line({ attributes: { class: 'cm-current-block', 'data-line': String(line.number) } }).range(line.from),
    ]);
  }),
  gutterLineClass.compute([currentBlock], (state) => {
    const pos = state.field(currentBlock);
    if (pos < 0 || pos > state.doc.length) return RangeSet.empty;
    return RangeSet.of([currentGutter.range(state.doc.lineAt(pos).from)]);
  }),
];

export class Editor {
  constructor(host) {
    this.host = host;
    host.classList.add('editor');
    host.editor = this; // the browser tests reach the editor through its element
    this.onChange = () => {};
    this.onCursorLine = () => {};
    this.cursorLine = 0;
    const listener = EditorView.updateListener.of((u) => {
      if (u.docChanged) this.onChange(u);
      if (u.docChanged || u.selectionSet) {
        const line = u.state.doc.lineAt(u.state.selection.main.head).number;
        if (line !== this.cursorLine) {
          this.cursorLine = line;
          this.onCursorLine(line);
        }
      }
    });
    this.extensions = [
      lineNumbers(),
      highlightActiveLineGutter(),
      highlightSpecialChars(),
      history(),
      drawSelection(),
      rectangularSelection(),
      highlightActiveLine(),
      highlightSelectionMatches(),
      lintGutter(),
      fanuc(),
      currentDecorations,
      currentBlock,
      listener,
      EditorState.tabSize.of(2),
      keymap.of([...defaultKeymap, ...historyKeymap, ...searchKeymap, ...lintKeymap, indentWithTab]),
      EditorView.contentAttributes.of({ 'aria-label': 'program text', spellcheck: 'false' }),
    ];
    this.view = new EditorView({ state: this.newState(''), parent: host });
  }

  newState(doc) {
    return EditorState.create({ doc, extensions: this.extensions });
  }

  get text() {
    return this.view.state.doc.toString();
  }

  // A new text: a new undo history, no marks, no current block, the cursor at the top.
  set text(t) {
    this.cursorLine = 1;
    this.view.setState(this.newState(t));
  }

  // The document as an object that is replaced by every edit (CodeMirror's are immutable):
  // the same object means the same text, found without building the text (0.4-0.6 s for a
  // million lines).
  get doc() {
    return this.view.state.doc;
  }

  get lineCount() {
    return this.view.state.doc.lines;
  }

  // marks: [{line, kind: 'alarm'|'warning', text}]; lines outside the text are dropped.
  setMarks(marks) {
    const doc = this.view.state.doc;
    const diagnostics = [];
    for (const m of marks) {
      if (!(m.line >= 1 && m.line <= doc.lines)) continue;
      const l = doc.line(m.line);
      diagnostics.push({ from: l.from, to: l.to, severity: m.kind === 'alarm' ? 'error' : 'warning', message: m.text });
    }
    this.view.dispatch(setDiagnostics(this.view.state, diagnostics));
  }

  // The marks shown, as [{line, kind, text}] (for the tests and the messages).
  marks() {
    const out = [];
    const doc = this.view.state.doc;
    forEachDiagnostic(this.view.state, (d, from) =>
      out.push({ line: doc.lineAt(from).number, kind: d.severity === 'error' ? 'alarm' : 'warning', text: d.message }));
    return out;
  }

  // The timeline's block: highlighted, and scrolled into view when `reveal` and out of view.
  setCurrent(line, reveal = true) {
    const doc = this.view.state.doc;
    const pos = line >= 1 && line <= doc.lines ? doc.line(line).from : -1;
    if (pos === this.view.state.field(currentBlock)) return;
    const effects = [setCurrentBlock.of(pos)];
    if (reveal && pos >= 0 && !this.isVisible(pos)) effects.push(EditorView.scrollIntoView(pos, { y: 'center' }));
    this.view.dispatch({ effects });
  }

  get current() {
    const pos = this.view.state.field(currentBlock);
    return pos < 0 ? 0 : this.view.state.doc.lineAt(pos).number;
  }

  isVisible(pos) {
    const { from, to } = this.view.viewport;
    if (pos < from || pos > to) return false;
    const block = this.view.lineBlockAt(pos);
    const top = this.view.scrollDOM.scrollTop, h = this.view.scrollDOM.clientHeight;
    return block.top >= top && block.bottom <= top + h;
  }

  // The cursor to the start of a line, scrolled to the middle (a pick in the 3D view).
  selectLine(line) {
    const doc = this.view.state.doc;
    if (!(line >= 1 && line <= doc.lines)) return;
    const l = doc.line(line);
    this.view.dispatch({ selection: { anchor: l.from, head: l.to }, effects: EditorView.scrollIntoView(l.from, { y: 'center' }) });
  }

  find() {
    openSearchPanel(this.view);
  }

  goToLine() {
    gotoLine(this.view);
  }

  // After the editor's pane was hidden: measure again.
  render() {
    this.view.requestMeasure();
  }

  focus() {
    this.view.focus();
  }
}
