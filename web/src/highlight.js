// Fanuc program text -> HTML with one span per token, for the editor overlay. A tokenizer,
// not a parser: the server's check and run report the real errors.
const KEYWORDS = new Set([
  'IF', 'THEN', 'GOTO', 'WHILE', 'DO', 'END', 'EQ', 'NE', 'GT', 'GE', 'LT', 'LE', 'AND', 'OR', 'XOR',
  'MOD', 'SIN', 'COS', 'TAN', 'ASIN', 'ACOS', 'ATAN', 'SQRT', 'ABS', 'ROUND', 'FIX', 'FUP', 'BIN', 'BCD',
  'LN', 'EXP', 'POW', 'ADP', 'POPEN', 'PCLOS', 'DPRNT', 'BPRNT', 'SETVN',
]);

export function escapeHtml(s) {
  return s.replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
}

// Returns [{cls, text}] covering the whole line.
export function tokenize(line) {
  const out = [];
  let i = 0;
  const push = (cls, text) => out.push({ cls, text });
  while (i < line.length) {
    const c = line[i];
    const rest = line.slice(i);
    let m;
    if (c === '(') {
      const close = line.indexOf(')', i);
      const end = close < 0 ? line.length : close + 1;
      push('comment', line.slice(i, end));
      i = end;
    } else if (c === ';') {
      push('comment', rest);
      i = line.length;
    } else if (c === '%') {
      push('percent', c);
      i++;
    } else if (c === '/' && out.every((t) => t.cls === 'ws')) {
      push('skip', (m = /^\/\d?/.exec(rest))[0]);
      i += m[0].length;
    } else if ((m = /^#\d+/.exec(rest)) || (m = /^#(?=\[)/.exec(rest))) {
      push('var', m[0]);
      i += m[0].length;
    } else if ((m = /^[A-Z]{2,}/i.exec(rest)) && KEYWORDS.has(m[0].toUpperCase())) {
      push('kw', m[0]);
      i += m[0].length;
    } else if ((m = /^[OoNn]\d+/.exec(rest)) && out.every((t) => t.cls === 'ws' || t.cls === 'skip')) {
      push(/^[Oo]/.test(m[0]) ? 'prog' : 'seq', m[0]);
      i += m[0].length;
    } else if ((m = /^[Gg]\s*\d+(\.\d)?/.exec(rest))) {
      push('g', m[0]);
      i += m[0].length;
    } else if ((m = /^[Mm]\s*\d+/.exec(rest))) {
      push('m', m[0]);
      i += m[0].length;
    } else if ((m = /^[A-Za-z]\s*[-+]?(\d+\.?\d*|\.\d+)/.exec(rest))) {
      push('addr', m[0]);
      i += m[0].length;
    } else if ((m = /^(\d+\.?\d*|\.\d+)/.exec(rest))) {
      push('num', m[0]);
      i += m[0].length;
    } else if ((m = /^<[^>]*>/.exec(rest))) {
      push('prog', m[0]);
      i += m[0].length;
    } else if ((m = /^\s+/.exec(rest))) {
      push('ws', m[0]);
      i += m[0].length;
    } else {
      push(/[A-Za-z]/.test(c) ? 'addr' : 'op', c);
      i++;
    }
  }
  return out;
}

export function highlightLine(line) {
  return tokenize(line)
    .map((t) => (t.cls === 'ws' ? escapeHtml(t.text) : `<span class="t-${t.cls}">${escapeHtml(t.text)}</span>`))
    .join('');
}
