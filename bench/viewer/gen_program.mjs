// A CAM-like mill program for the viewer benchmark: `lines` moves in a zigzag of short G01
// steps (0.05-0.1 mm) over a 100 x 100 mm pocket, every tenth move a half-circle arc
// (G02/G03 with R), at one depth. It runs without alarm under ncvm's default setup.
//   node bench/viewer/gen_program.mjs 1000000 > big.nc
import { writeFileSync } from 'node:fs';

export function cncProgram(lines) {
  const out = ['O1000 (VIEWER BENCHMARK)', 'G21 G90 G17 G40 G49 G80 G54', 'G00 X0. Y0. Z5.', 'G01 Z-1. F2000.'];
  let x = 0, y = 0, dir = 1, arc = 0;
  const f = (v) => v.toFixed(3);
  for (let i = 0; i < lines; i++) {
    if (i % 10 === 9) {
      // A half circle of radius 0.05 along X, alternating sides.
      const nx = x + dir * 0.1;
      out.push(`${arc++ % 2 ? 'G02' : 'G03'} X${f(nx)} Y${f(y)} R0.05`);
      x = nx;
    } else {
      const nx = x + dir * 0.1;
      if (nx > 100 || nx < 0) {
        y += 0.1;
        if (y > 100) y = 0;
        dir = -dir;
        out.push(`G01 X${f(x)} Y${f(y)}`);
      } else {
        x = nx;
        out.push(`G01 X${f(x)} Y${f(y + ((i % 2) * 0.05))}`);
      }
    }
  }
  out.push('G00 Z5.', 'M30', '');
  return out.join('\n');
}

if (process.argv[1] && process.argv[1].endsWith('gen_program.mjs')) {
  const n = Number(process.argv[2] || 43000);
  const text = cncProgram(n);
  if (process.argv[3]) writeFileSync(process.argv[3], text);
  else process.stdout.write(text);
}
