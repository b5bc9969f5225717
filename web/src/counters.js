// What a control keeps across cycles, kept in this browser (localStorage): the alarm history
// (as the control's ALARM HISTORY screen, newest first), the run time (the cycle times of
// every run added up) and the parts counted (#3901 rises at M30).
const KEY = 'ncvm.counters', MAX_ALARMS = 50;

export function counters() {
  try {
    const c = JSON.parse(localStorage.getItem(KEY) || 'null');
    if (c && Array.isArray(c.alarms)) return c;
  } catch {
    /* a damaged entry starts again */
  }
  return { alarms: [], runTime: 0, runs: 0, parts: 0 };
}

// The parts this run counted: one at M30, as the control adds to #3901 (nc_block.cpp; the
// trace has no event after M30, so the states do not show it).
export function partsOfRun(model) {
  return model.answer.state?.end === 'M30' ? 1 : 0;
}

export function recordRun(model, program) {
  const c = counters();
  const a = model.answer.state || {};
  c.runs++;
  c.runTime += a.cycle_time || 0;
  c.parts += partsOfRun(model);
  if (a.alarm)
    c.alarms.unshift({ time: Date.now(), program, code: a.alarm.code, text: a.alarm.text, file: a.alarm.file, line: a.alarm.line, n: a.alarm.n });
  c.alarms.length = Math.min(c.alarms.length, MAX_ALARMS);
  localStorage.setItem(KEY, JSON.stringify(c));
  return c;
}

export function resetCounters() {
  localStorage.removeItem(KEY);
}
