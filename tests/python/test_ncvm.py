"""The Python module `ncvm` as installed (tests/CMakeLists.txt runs pytest with PYTHONPATH at
an installed prefix): run, check, results, errors, and the plotting example."""
import json
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import ncvm

PREFIX = pathlib.Path(os.environ.get("NCVM_PREFIX", "/usr"))
EXAMPLES = PREFIX / "share" / "ncvm" / "examples"
NCVM_BIN = PREFIX / "bin" / "ncvm"
SOURCE = pathlib.Path(__file__).resolve().parents[2]


def test_the_module_is_the_installed_one():
    # Not a copy from the source or build tree: the prefix's own.
    assert pathlib.Path(ncvm.__file__).resolve().is_relative_to(PREFIX.resolve())
    assert ncvm.data_folder() == str(PREFIX / "share" / "ncvm")


def test_run_text_gives_end_moves_and_state():
    r = ncvm.run("%\nO1\nG90 G0 X10. Y0\nG1 X20. F100.\nG2 X30. Y10. R10.\nM30\n%\n")
    assert r.end == "M30"
    assert r.alarm is None
    m = r.moves
    assert m.dtype == ncvm.MOVE_DTYPE
    assert list(m["kind"]) == ["rapid", "linear", "cw"]
    assert m["start"].shape == (3, 6)
    np.testing.assert_allclose(m["start"][1, :3], [10, 0, 0])
    np.testing.assert_allclose(m["end"][1, :3], [20, 0, 0])
    assert m["feed"][1] == 100
    assert m["line"].tolist() == [3, 4, 5]
    assert m["time"][1] == pytest.approx(6.0)  # 10 mm at 100 mm/min
    # G2 R10 from (20,0) to (30,10): clockwise a quarter circle about (30,0)
    np.testing.assert_allclose(m["center"][2, :2], [30, 0])
    assert r.state["end"] == "M30"
    assert r.stats["moves"] == 3


def test_state_is_what_the_command_writes(tmp_path):
    prog = EXAMPLES / "macro-basics" / "bolt-circle.nc"
    state = tmp_path / "state.json"
    subprocess.run([NCVM_BIN, "run", prog, "--state", state, "-q"], check=True)
    r = ncvm.run(str(prog))
    assert r.state == json.loads(state.read_text())
    assert len(r.moves) == r.state["moves"]
    assert r.moves["time"].sum() == pytest.approx(r.state["cycle_time"], rel=1e-9)


def test_paths_presets_and_sets():
    prog = EXAMPLES / "lathe-cycles" / "g71-g70-rough-turning.nc"
    lathe = ncvm.run(prog, setup=["fanuc-0i-tf", prog.parent / "setup.toml"])
    assert lathe.alarm is None, lathe.alarm
    assert lathe.state["modal"]["2"] == 97  # a lathe's group 2 is G96/G97, a mill's the plane
    assert ncvm.run(prog).state["modal"]["2"] != 97
    # Without a decimal point X1 is one least increment; DPI=1 makes it 1 mm.
    assert ncvm.run("G0 X1\nM30\n").moves["end"][0, 0] == pytest.approx(0.001)
    assert ncvm.run("G0 X1\nM30\n", sets={"DPI": 1}).moves["end"][0, 0] == pytest.approx(1)
    assert ncvm.run("G0 X1\nM30\n", sets=["DPI=1"]).moves["end"][0, 0] == pytest.approx(1)


def test_an_alarm_has_code_message_and_place():
    r = ncvm.run("G0 X1.\n#1=1/0\nM30\n")
    assert r.end == "alarm"
    a = r.alarm
    assert a.code == "PS0112"
    assert a.message
    assert (a.file, a.line) == ("<text>", 2)
    assert a.column > 0
    assert "PS0112" in str(a)


def test_errors_of_use_raise():
    with pytest.raises(ncvm.Error):
        ncvm.run("G0 X1\nM30\n", sets={"no_such_section.key": 1})
    with pytest.raises(ncvm.Error):
        ncvm.run("G0 X1\nM30\n", setup="no-such-preset")
    with pytest.raises(FileNotFoundError):
        ncvm.run("missing/part.nc")
    with pytest.raises(TypeError):
        ncvm.run(42)


def test_check_finds_without_running():
    c = ncvm.check("G1 X1. X2. F100\nM30\n")
    assert c.ok
    assert any(w.code == "W002" and w.line == 1 for w in c.warnings)
    assert c.report["warnings"]
    # A GOTO to a label that is not there: an alarm only if it runs, so a warning here.
    c = ncvm.check("GOTO 99\nM30\n")
    assert c.ok and [w.code for w in c.warnings] == ["PS0128"]
    # A call to a program that is nowhere: the run alarms; with the bundled macros O9135 is
    # there, without them it is not.
    assert ncvm.run("G65 P4321\nM30\n").alarm.code == "PS0076"


def test_the_plotting_example_draws_a_toolpath(tmp_path):
    out = tmp_path / "toolpath.png"
    env = dict(os.environ, MPLBACKEND="Agg")
    script = SOURCE / "examples" / "python" / "plot_toolpath.py"
    subprocess.run([sys.executable, script, EXAMPLES / "macro-basics" / "bolt-circle.nc",
                    "--out", out], check=True, env=env)
    data = out.read_bytes()
    assert data.startswith(b"\x89PNG")
    assert len(data) > 10000  # a drawing, not an empty canvas
