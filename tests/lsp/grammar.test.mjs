// The VS Code extension's TextMate grammar (editors/vscode/syntaxes/fanuc.tmLanguage.json),
// tokenised by the engine VS Code itself uses (vscode-textmate with the Oniguruma regex
// library, tests/lsp/package-lock.json): each kind of word gets its scope.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import textmate from 'vscode-textmate';
import oniguruma from 'vscode-oniguruma';

const here = dirname(fileURLToPath(import.meta.url));
const require = createRequire(import.meta.url);
const grammarPath = join(here, '..', '..', 'editors', 'vscode', 'syntaxes', 'fanuc.tmLanguage.json');

async function loadGrammar() {
  const wasm = readFileSync(join(dirname(require.resolve('vscode-oniguruma')), 'onig.wasm'));
  await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
  const registry = new textmate.Registry({
    onigLib: Promise.resolve({
      createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
      createOnigString: (s) => new oniguruma.OnigString(s),
    }),
    loadGrammar: async (scope) =>
      scope === 'source.fanuc'
        ? textmate.parseRawGrammar(readFileSync(grammarPath, 'utf8'), grammarPath)
        : null,
  });
  return registry.loadGrammar('source.fanuc');
}

// [text, innermost scope] of each token of a line.
function tokens(grammar, line) {
  const r = grammar.tokenizeLine(line, textmate.INITIAL);
  return r.tokens.map((t) => [line.slice(t.startIndex, t.endIndex), t.scopes.at(-1)]);
}

function scopeOf(list, text) {
  const hit = list.find(([t]) => t.trim() === text);
  assert.ok(hit, `no token "${text}" in ${JSON.stringify(list)}`);
  return hit[1];
}

test('the grammar gives each kind of word its scope', async () => {
  const grammar = await loadGrammar();
  assert.ok(grammar, 'the grammar loads');
  let t = tokens(grammar, 'N10 G01 X-1.5 Y2. F100 M08 (ROUGH X PASS)');
  assert.equal(scopeOf(t, 'N10'), 'entity.name.tag.sequence.fanuc');
  assert.equal(scopeOf(t, 'G'), 'support.function.gcode.fanuc');
  assert.equal(scopeOf(t, '01'), 'support.function.gcode.fanuc');
  assert.equal(scopeOf(t, 'X'), 'variable.parameter.address.fanuc');
  assert.equal(scopeOf(t, '-1.5'), 'constant.numeric.fanuc');
  assert.equal(scopeOf(t, 'M'), 'keyword.control.mcode.fanuc');
  assert.equal(scopeOf(t, 'ROUGH X PASS'), 'comment.block.fanuc'); // no address X inside

  t = tokens(grammar, 'O0100 (MAIN)');
  assert.equal(scopeOf(t, '0100'), 'entity.name.function.program.fanuc');

  t = tokens(grammar, 'IF[#1GT#5021]GOTO10');
  assert.equal(scopeOf(t, 'IF'), 'keyword.control.macro.fanuc');
  assert.equal(scopeOf(t, 'GT'), 'keyword.operator.word.fanuc');
  assert.equal(scopeOf(t, '#5021'), 'variable.other.macro.fanuc');
  assert.equal(scopeOf(t, 'GOTO'), 'keyword.control.macro.fanuc');

  t = tokens(grammar, '#100=SQRT[#1*#1]+ATAN[#2]/[#3]');
  assert.equal(scopeOf(t, '#100'), 'variable.other.macro.fanuc');
  assert.equal(scopeOf(t, 'SQRT'), 'support.function.macro.fanuc');
  assert.equal(scopeOf(t, 'ATAN'), 'support.function.macro.fanuc');

  t = tokens(grammar, 'WHILE [#2 LE 10] DO1');
  assert.equal(scopeOf(t, 'WHILE'), 'keyword.control.macro.fanuc');
  assert.equal(scopeOf(t, 'DO'), 'keyword.control.macro.fanuc');

  t = tokens(grammar, '/2 M98 <POCKET_SUB>');
  assert.equal(scopeOf(t, '/2'), 'keyword.other.block-skip.fanuc');
  assert.equal(scopeOf(t, '<POCKET_SUB>'), 'entity.name.function.program.fanuc');
  assert.equal(scopeOf(tokens(grammar, '%'), '%'), 'keyword.other.tape-start.fanuc');
});
