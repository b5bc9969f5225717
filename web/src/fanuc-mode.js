// The editor's Fanuc / Macro B language mode for CodeMirror 6: the tokenizer of highlight.js
// as a stream parser, each kind of token a highlighting tag with a class of its own (t-g,
// t-kw, ...; colours in style.css, so that both themes style them).
import { StreamLanguage, syntaxHighlighting } from '@codemirror/language';
import { Tag, tags, tagHighlighter } from '@lezer/highlight';
import { nextToken, keepsHead } from './highlight.js';

// A tag per token class; each a sub-tag of a standard one so other highlighters also work.
const TAGS = {
  comment: tags.comment,
  percent: Tag.define(tags.processingInstruction),
  skip: Tag.define(tags.modifier),
  var: tags.variableName,
  kw: tags.keyword,
  prog: Tag.define(tags.heading),
  seq: tags.labelName,
  g: Tag.define(tags.typeName),
  m: Tag.define(tags.macroName),
  addr: tags.propertyName,
  num: tags.number,
  op: tags.operator,
};

const fanucParser = {
  name: 'fanuc',
  startState: () => ({ head: true }),
  token(stream, state) {
    if (stream.sol()) state.head = true;
    const t = nextToken(stream.string, stream.pos, state.head);
    stream.pos = Math.max(t.end, stream.pos + 1);
    state.head = state.head && keepsHead(t.cls);
    return t.cls === 'ws' ? null : t.cls;
  },
  tokenTable: TAGS,
  languageData: { commentTokens: { block: { open: '(', close: ')' } } },
};

export const fanucLanguage = StreamLanguage.define(fanucParser);

const classes = tagHighlighter(Object.entries(TAGS).map(([cls, tag]) => ({ tag, class: `t-${cls}` })));

export function fanuc() {
  return [fanucLanguage, syntaxHighlighting(classes)];
}
