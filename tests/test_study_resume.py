"""A study loses nothing: a step that fails still writes the report of what finished, marked
incomplete; a study killed (SIGINT, SIGKILL) at different steps resumes with ``--resume`` and
gives the results of an uninterrupted run; a sea state name with '/', spaces and brackets
makes safe file names."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

import jaxtow as jt
from jaxtow.cli import main

SMALL = ["--map-xp", "0.2", "0.6", "3", "--map-l0", "1.0", "2.5", "2", "--t1", "40"]
SMALL += ["--speeds", "0", "3", "4", "--risk", "never"]  # the Monte Carlo: tests/test_risk.py


def _summary(folder: Path, stem: str) -> dict:
    s = json.loads((folder / f"{stem}_summary.json").read_text())
    s.pop("step_times_s")
    return s


def test_failure_in_a_step_writes_the_report_marked_incomplete(tmp_path, monkeypatch, capsys):
    """The first step of Barge 1's study (its drift) forced to fail: the report and the JSON
    name the step and the error under names of their own (a complete report of an earlier
    run in the folder stays as it was), the command exits 1 and keeps its step folder; a
    second study in the same folder keeps its own run manifest."""
    (tmp_path / "barge1_report.html").write_text("the complete report of an earlier run")

    def fail(self):
        raise RuntimeError("forced failure")

    monkeypatch.setattr(jt.presets.AbstractDriftSource, "qtf", fail)
    with pytest.raises(SystemExit) as info:
        main(["study", "barge1", "--out", str(tmp_path), "--quiet"])
    assert info.value.code == 1
    s = json.loads((tmp_path / "barge1_INCOMPLETE_summary.json").read_text())
    assert s["incomplete"] == dict(
        step="wave drift of the hull", error="RuntimeError: forced failure", interrupted=False
    )
    text = (tmp_path / "barge1_INCOMPLETE_report.html").read_text()
    assert "Tow study: barge1 (INCOMPLETE)" in text
    assert "RuntimeError: forced failure" in text and "--resume" in text
    assert (tmp_path / "barge1_report.html").read_text() == "the complete report of an earlier run"
    assert "--resume to continue" in capsys.readouterr().err
    assert (tmp_path / ".barge1_steps" / "manifest.json").exists()
    assert json.loads((tmp_path / "barge1_run.json").read_text())["status"] == "failed"
    assert not (tmp_path / "jaxtow_run.json").exists()
    assert not list(tmp_path.glob("*.lock"))


def test_resume_of_another_study_is_refused(tmp_path):
    store = jt.io.StepStore(tmp_path / "s", "a" * 64, resume=False)
    store.put("calm", {"x": 1})
    assert jt.io.StepStore(tmp_path / "s", "a" * 64, resume=True).get("calm") == {"x": 1}
    with pytest.raises(ValueError, match=r"--resume: .* holds the steps of another study"):
        jt.io.StepStore(tmp_path / "s", "b" * 64, resume=True)
    assert jt.io.StepStore(tmp_path / "s", "b" * 64, resume=False).get("calm") is None


def _tow_with_odd_names(tmp_path: Path) -> Path:
    text = jt.tow.builtin_text("barge2a").replace('name = "barge2a"', 'name = "my barge/2a"')
    text = text.replace(
        '[[sea_state]]\nbuiltin = "sailing"',
        '[[sea_state]]\nname = "TPR (20 m/s, Hs 5 m, 0.5 m/s)"\nhs = 3.0\ntp = 8.0\n'
        "wind_speed = 20.0",
    )
    f = tmp_path / "odd.toml"
    f.write_text(text)
    return f


def _study(args, **kw):
    return subprocess.Popen(
        [sys.executable, "-c", "from jaxtow.cli import main; main()", "study", *args],
        stderr=subprocess.PIPE,
        stdout=subprocess.PIPE,
        text=True,
        env=dict(os.environ, PYTHONUNBUFFERED="1"),
        **kw,
    )


def _kill_after(args, step: int, sig) -> subprocess.Popen:
    """Run the study and send ``sig`` as soon as step ``step`` reports done."""
    p = _study(args)
    assert p.stderr is not None
    for line in p.stderr:
        if line.startswith(f"[{step}/") and ": done in" in line:
            p.send_signal(sig)
            break
    p.communicate(timeout=300)
    return p


@pytest.mark.heavy  # minutes on 2 cores: pytest -m heavy
@pytest.mark.slow
def test_killed_study_resumes_to_the_uninterrupted_results(tmp_path):
    tow = _tow_with_odd_names(tmp_path)
    stem = "my_barge_2a"
    ref = tmp_path / "ref"
    p = _study([str(tow), "--out", str(ref), *SMALL])
    out, err = p.communicate(timeout=600)
    assert p.returncode == 0, err
    names = sorted(f.name for f in ref.iterdir())
    assert f"{stem}_operating_point_TPR_20_m_s_Hs_5_m_0.5_m_s.png" in names
    assert not [n for n in names if n.startswith(".") or n.endswith(".lock")]
    reference = _summary(ref, stem)
    assert reference["incomplete"] is None
    ref_map = xr.load_dataset(ref / f"{stem}_map_xp_l0.nc")

    for step, sig in ((2, signal.SIGINT), (5, signal.SIGKILL)):
        out = tmp_path / f"killed_{step}"
        p = _kill_after([str(tow), "--out", str(out), *SMALL], step, sig)
        if sig == signal.SIGINT:  # Ctrl-C: the report of what finished, marked incomplete
            assert p.returncode == 130
            s = json.loads((out / f"{stem}_INCOMPLETE_summary.json").read_text())
            assert s["incomplete"]["interrupted"] is True
            assert "(INCOMPLETE)" in (out / f"{stem}_INCOMPLETE_report.html").read_text()
        else:
            assert p.returncode == -signal.SIGKILL
        kept = list((out / f".{stem}_steps").glob("*.pickle"))
        assert len(kept) >= step
        p = _study([str(tow), "--out", str(out), "--resume", *SMALL])
        _, err = p.communicate(timeout=600)
        assert p.returncode == 0, err
        assert err.count(": resumed") == len(kept)
        assert _summary(out, stem) == reference
        assert not list(out.glob(f"{stem}_INCOMPLETE_*"))  # the complete run removes them
        xr.testing.assert_identical(xr.load_dataset(out / f"{stem}_map_xp_l0.nc"), ref_map)
        assert not (out / f".{stem}_steps").exists()
        assert not list(out.glob("*.lock"))


@pytest.mark.slow
def test_failure_in_the_last_step_keeps_every_earlier_result(tmp_path, monkeypatch):
    def fail(*args, **kw):
        raise RuntimeError("forced failure in the time domain")

    monkeypatch.setattr("jaxtow.studies._assessment.simulate", fail)
    with pytest.raises(SystemExit):
        main(["study", "barge2a", "--out", str(tmp_path), "--quiet", *SMALL])
    s = json.loads((tmp_path / "barge2a_INCOMPLETE_summary.json").read_text())
    assert s["incomplete"]["step"] == "time-domain check from a disturbed start"
    assert {"conditions", "resistance", "map"} <= set(s) and len(s["conditions"]) >= 3
    assert s["time_domain"] is None
    text = (tmp_path / "barge2a_INCOMPLETE_report.html").read_text()
    assert "(INCOMPLETE)" in text and "forced failure in the time domain" in text
    assert np.isfinite(s["map"]["straight_stable_share"])


def test_a_swallowed_ctrl_c_still_stops_the_study_at_the_next_step():
    """A Ctrl-C whose KeyboardInterrupt is swallowed on its way (a finaliser, a callback that
    ignores exceptions) is remembered: the study's next step boundary stops it."""
    from jaxtow._interrupt import sticky_interrupts as sticky
    from jaxtow.studies._assessment import Steps

    def swallow():
        try:
            os.kill(os.getpid(), signal.SIGINT)
            for _ in range(1000):  # the interrupt lands at a bytecode in here
                pass
        except KeyboardInterrupt:
            pass

    steps = Steps(2, enabled=False)
    with sticky():
        with pytest.raises(KeyboardInterrupt):
            steps.run("one", "one", swallow)  # the step finishes, then the study stops
        assert "one" in steps.times and steps.k == 1
        with pytest.raises(KeyboardInterrupt):
            steps.run("two", "two", lambda: None)
    assert steps.k == 1  # the second step never started


def test_a_ctrl_c_outside_the_command_line_does_not_stop_a_later_study():
    """Outside `sticky_interrupts` (a notebook, a script) an interrupt recorded by a held write is not
    remembered, and when `sticky` ends its record goes with it: a later study runs."""
    from jaxtow._interrupt import request, requested, sticky_interrupts as sticky
    from jaxtow.studies._assessment import Steps

    request()
    assert not requested()
    with sticky():
        request()
        assert requested()
    assert not requested()
    steps = Steps(1, enabled=False)
    assert steps.run("one", "one", lambda: 1) == 1
