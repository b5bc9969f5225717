// Fanuc / Custom Macro B program text split into tokens: one tokenizer for the editor's
// language mode (fanuc-mode.js) and the tests. A tokenizer, not a parser: the server's check
// and run report the real errors. Lines are independent (a Fanuc comment ends with its block).
const KEYWORDS = new Set([
  'IF', 'THEN', 'GOTO', 'WHILE', 'DO', 'END', 'EQ', 'NE', 'GT', 'GE', 'LT', 'LE', 'AND', 'OR', 'XOR',
  'MOD', 'SIN', 'COS', 'TAN', 'ASIN', 'ACOS', 'ATAN', 'SQRT', 'ABS', 'ROUND', 'FIX', 'FUP', 'BIN', 'BCD',
  'LN', 'EXP', 'POW', 'ADP', 'POPEN', 'PCLOS', 'DPRNT', 'BPRNT', 'SETVN',
]);

export function escapeHtml(s) {
  return s.replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
}

const at = (re, line, i) => {
  re.lastIndex = i;
  const m = re.exec(line);
  return m ? m[0].length : 0;
};
const SKIP = /\/\d?/y, VAR = /#\d+|#(?=\[)/y, WORD = /[A-Z]{2,}/iy, LABEL = /[OoNn]\d+/y;
const GCODE = /[Gg]\s*\d+(\.\d)?/y, MCODE = /[Mm]\s*\d+/y, ADDR = /[A-Za-z]\s*[-+]?(\d+\.?\d*|\.\d+)/y;
const NUM = /\d+\.?\d*|\.\d+/y, NAME = /<[^>]*>/y, WS = /\s+/y;

// The token at line[i]: {cls, end}. `head`: only blanks and a block skip before it, where an
// O number names a program and an N number is a sequence number.
export function nextToken(line, i, head) {
  const c = line[i];
  let n;
  if (c === '(') {
    const close = line.indexOf(')', i);
    return { cls: 'comment', end: close < 0 ? line.length : close + 1 };
  }
  if (c === ';') return { cls: 'comment', end: line.length };
  if (c === '%') return { cls: 'percent', end: i + 1 };
  if ((n = at(WS, line, i))) return { cls: 'ws', end: i + n };
  if (c === '/' && head) return { cls: 'skip', end: i + at(SKIP, line, i) };
  if ((n = at(VAR, line, i))) return { cls: 'var', end: i + n };
  if ((n = at(WORD, line, i)) && KEYWORDS.has(line.slice(i, i + n).toUpperCase())) return { cls: 'kw', end: i + n };
  if (head && (n = at(LABEL, line, i))) return { cls: /[Oo]/.test(c) ? 'prog' : 'seq', end: i + n };
  if ((n = at(GCODE, line, i))) return { cls: 'g', end: i + n };
  if ((n = at(MCODE, line, i))) return { cls: 'm', end: i + n };
  if ((n = at(ADDR, line, i))) return { cls: 'addr', end: i + n };
  if ((n = at(NUM, line, i))) return { cls: 'num', end: i + n };
  if ((n = at(NAME, line, i))) return { cls: 'prog', end: i + n };
  return { cls: /[A-Za-z]/.test(c) ? 'addr' : 'op', end: i + 1 };
}

// Whether a token keeps the block's head open (blanks and a block skip do).
export const keepsHead = (cls) => cls === 'ws' || cls === 'skip';

// Returns [{cls, text}] covering the whole line.
export function tokenize(line) {
  const out = [];
  let head = true;
  for (let i = 0; i < line.length; ) {
    const t = nextToken(line, i, head);
    out.push({ cls: t.cls, text: line.slice(i, t.end) });
    head = head && keepsHead(t.cls);
    i = t.end;
  }
  return out;
}
