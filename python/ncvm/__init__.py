"""ncvm: run and check Fanuc part programs from Python (docs/embedding.md).

    import ncvm
    r = ncvm.run("part.nc", setup="fanuc-0i-mf", sets={"DPI": 1})
    if r.alarm:
        print(r.alarm)                      # part.nc:12:5: PS0010 IMPROPER G-CODE
    print(r.end, r.state["position"])       # the --state JSON as a dict
    xyz = r.moves["end"][:, :3]             # numpy: one row per move

The engine is ncvm's own (the same as the ncvm command): a run gives what `ncvm run` gives
with the same setup and files.
"""
import json
import os

import numpy as np

from ._ncvm import Alarm, Error, Job, Warning, data_folder, version

__all__ = ["run", "check", "Result", "CheckResult", "Alarm", "Warning", "Error", "Job",
           "MOVE_DTYPE", "MOVE_KINDS", "version", "data_folder"]

# The kinds of move, as the `kind` field of Result.moves holds them.
MOVE_KINDS = ("rapid", "linear", "cw", "ccw")
# One move: start and end in work coordinates (X Y Z A B C, program units, a lathe's X as a
# diameter), the arc centre (X Y Z) and plane (17/18/19), feed (units/min, 0 for rapids),
# path length, time (seconds), and the block's line and N number (-1: none).
MOVE_DTYPE = np.dtype([
    ("start", "f8", (6,)), ("end", "f8", (6,)), ("kind", "U6"), ("feed", "f8"),
    ("line", "u4"), ("time", "f8"), ("length", "f8"), ("center", "f8", (3,)),
    ("plane", "u1"), ("n", "i4"),
])
# A string that names a program file (rather than holding program text), when it names none.
_PROGRAM_SUFFIXES = (".nc", ".ptp", ".eia", ".min", ".tap", ".txt", ".cnc", ".ngc")


class Result:
    """A run: end ("M30", "M02", "M99", "alarm", ...), alarm (None or an Alarm), warnings,
    state (dict, as `ncvm run --state`), moves (numpy array of MOVE_DTYPE), stats (dict),
    printed (DPRNT/BPRNT output, bytes)."""

    def __init__(self, end, alarm, warnings, stats, state_json, printed, columns):
        self.end = end
        self.alarm = alarm
        self.warnings = list(warnings)
        self.stats = dict(stats)
        self.state_json = state_json
        self.printed = printed
        self._columns = columns
        self._state = None
        self._moves = None

    @property
    def state(self):
        if self._state is None:
            self._state = json.loads(self.state_json)
        return self._state

    @property
    def moves(self):
        if self._moves is None:
            c = self._columns
            moves = np.zeros(len(c["kind"]), dtype=MOVE_DTYPE)
            for name in ("start", "end", "feed", "line", "time", "length", "center", "plane", "n"):
                moves[name] = c[name]
            moves["kind"] = np.array(MOVE_KINDS)[c["kind"]] if len(c["kind"]) else []
            self._moves = moves
        return self._moves

    def __repr__(self):
        alarm = f", alarm={self.alarm.code}" if self.alarm else ""
        return f"<ncvm.Result end={self.end}{alarm}, {len(self._columns['kind'])} moves>"


class CheckResult:
    """A check: alarms and warnings (lists), ok (no alarm), report (dict, as
    `ncvm check --json`)."""

    def __init__(self, alarms, warnings, report_json):
        self.alarms = list(alarms)
        self.warnings = list(warnings)
        self.report = json.loads(report_json)

    @property
    def ok(self):
        return not self.alarms

    def __repr__(self):
        return f"<ncvm.CheckResult {len(self.alarms)} alarm(s), {len(self.warnings)} warning(s)>"


def _as_list(value):
    if value is None:
        return []
    if isinstance(value, (list, tuple)):
        return list(value)
    return [value]


def _add_program(job, program):
    if isinstance(program, bytes):
        job.add_program_text(program, "<text>")
    elif isinstance(program, os.PathLike):
        job.add_program_file(os.fspath(program))
    elif isinstance(program, str):
        if "\n" not in program and os.path.isfile(program):
            job.add_program_file(program)
        elif "\n" not in program and (program.lower().endswith(_PROGRAM_SUFFIXES)
                                      or os.sep in program):
            raise FileNotFoundError(f"{program}: no such program file")
        else:
            job.add_program_text(program.encode("utf-8"), "<text>")
    else:
        raise TypeError(f"a program is text, bytes or a path, not {type(program).__name__}")


def _add_setup(job, setup):
    for s in _as_list(setup):
        s = os.fspath(s)
        if os.path.isfile(s) or s.endswith(".toml") or os.sep in s:
            job.load_setup(s)
        else:
            job.load_preset(s)  # a bundled preset: "fanuc-0i-mf"


def _add_sets(job, sets):
    if isinstance(sets, dict):
        items = [f"{k}={_setting(v)}" for k, v in sets.items()]
    else:
        items = _as_list(sets)
    for kv in items:
        job.set(kv)


def _setting(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


def _job(program, setup, sets, lib, macros):
    job = Job()
    _add_setup(job, setup)
    _add_sets(job, sets)
    for p in _as_list(program):
        _add_program(job, p)
    for folder in _as_list(lib):
        job.add_folder(os.fspath(folder))
    job.use_bundled_macros(macros)
    return job


def run(text_or_path, setup=None, sets=None, lib=None, macros=True):
    """Runs a program and returns a Result.

    text_or_path: program text (str with a newline, or bytes), or a program file (a path, or
    a str naming an existing file); a list: the first one runs, the others are there for
    calls. setup: a setup file, a bundled preset's name ("fanuc-0i-mf") or a list of them
    (later ones override). sets: {"DPI": 1, "3401#0": 1} or ["DPI=1"], as --set. lib: a
    folder (or list) of programs for M98/G65. macros: load the bundled macros/ folder.
    Alarms of the program are in the result; errors of use raise ncvm.Error.
    """
    return Result(*_job(text_or_path, setup, sets, lib, macros).run())


def check(text_or_path, setup=None, sets=None, lib=None, macros=True):
    """What can be found without running (as `ncvm check`): a CheckResult."""
    return CheckResult(*_job(text_or_path, setup, sets, lib, macros).check())
