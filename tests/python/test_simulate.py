"""simulate against the scene's own model runs (the same doubles), the fitted law put back, and
run_scene's summary."""
import numpy as np
import pytest

from conftest import read_csv, read_summary, run_cli

DATA = "data/sample_rdelta_pva_control.csv"


def scene_with(tmp_path, run, body=""):
    scene = tmp_path / "scene.prm"
    scene.write_text(f"set Run = {run}\n" + body)
    return str(scene)


@pytest.mark.parametrize("model", ["beam", "fem"])
def test_simulate_is_the_scene_s_model_on_the_defaults(fb, tmp_path, model):
    out = tmp_path / "out"
    run_cli("run", scene_with(tmp_path, model), "--set", f"Output directory={out}")
    s = read_summary(out)[model]
    sim = fb.simulate(model=model)
    assert sim.model == model
    assert sim.G_ss_J_m2 == s["G_ss_J_m2"]
    assert sim.steady_state_status == s["steady_state_status"]
    rc = read_csv(f"{out}/rcurve_{model}.csv")
    assert len(sim.a_mm) == len(rc["a_mm"])
    # 10 significant digits in the CSV (core/csv.cc).
    np.testing.assert_allclose(sim.a_mm, rc["a_mm"], rtol=1e-9)
    np.testing.assert_allclose(sim.load_N, rc["load_N"], rtol=1e-9, atol=1e-12)


def test_the_fitted_law_goes_back_as_the_scene_s_fit_hands_it(fb, tmp_path):
    fit = fb.fit_trilinear(fb.extract(DATA))
    sim = fb.simulate(fit, model="beam")
    out = tmp_path / "out"
    body = f"subsection Data\n  set File = {__import__('os').path.abspath(DATA)}\nend\n"
    run_cli("run", scene_with(tmp_path, "fit, beam", body), "--set", f"Output directory={out}")
    s = read_summary(out)["beam"]
    assert s["law_source"] == "fit"
    assert sim.J_tip_law_J_m2 == s["J_tip_J_m2"]
    assert sim.G_ss_J_m2 == s["G_ss_J_m2"]


def test_specimen_keywords_reach_the_model(fb):
    narrow = fb.simulate(model="beam", width_mm=20)
    wide = fb.simulate(model="beam")
    # G_ss is per unit width: the same; the load scales with the width (35 mm by default).
    assert narrow.G_ss_J_m2 == pytest.approx(wide.G_ss_J_m2, rel=1e-6)
    assert max(narrow.load_N) == pytest.approx(max(wide.load_N) * 20 / 35, rel=1e-6)


def test_model_errors_are_input_errors(fb):
    with pytest.raises(fb.InputError, match="unknown model 'pd'"):
        fb.simulate(model="pd")
    with pytest.raises(fb.InputError, match="Beam/Number of elements|Number of elements"):
        fb.simulate(model="beam", settings={"Beam/Number of elements": -3})


def test_run_scene_returns_its_summary(fb, tmp_path):
    out = tmp_path / "out"
    summary = fb.run_scene(scene_with(tmp_path, "beam"), set={"Output directory": str(out)})
    assert summary == read_summary(out)
    assert summary["run"] == ["beam"]
    with pytest.raises(fb.InputError, match="scene file not found"):
        fb.run_scene(tmp_path / "nothing.prm")


def test_progress_gets_the_model_s_lines_and_changes_nothing(fb):
    lines = []
    sim = fb.simulate(model="fem", progress=lines.append)
    assert lines[0].startswith("fem (") and lines[-1].startswith("fem: done")
    assert any(line.startswith("fem: a = ") for line in lines)
    assert sim.G_ss_J_m2 == fb.simulate(model="fem").G_ss_J_m2


class Stop(Exception):
    pass


def test_an_exception_in_progress_stops_the_run(fb):
    seen = []

    def stop_at_the_second_line(line):
        seen.append(line)
        if len(seen) == 2:
            raise Stop(line)

    with pytest.raises(Stop):
        fb.simulate(model="fem", progress=stop_at_the_second_line)
    assert len(seen) == 2
    # The module is usable after the unwound run.
    assert fb.simulate(model="beam").reached_steady_state


# Ctrl-C in a long call: the FEM at 0.5 mm elements takes about a minute (29 progress lines, one
# every 2-3 s on this machine). SIGINT after the first line must end the call with
# KeyboardInterrupt at the next line, well before the run would have finished.
def interrupted_script(call):
    """A script that runs `call` (with progress=progress) and prints how long after its first
    progress line a KeyboardInterrupt stopped it (exit status 3)."""
    return f"""
import sys, time
import fiberbridge as fb
said = []
def progress(line):
    if not said:
        said.append(time.time())
        print("running", flush=True)
try:
    {call}
    print("finished", flush=True)
except KeyboardInterrupt:
    print("interrupted after %.1f s" % (time.time() - said[0]), flush=True)
    sys.exit(3)
"""


INTERRUPTED = interrupted_script(
    'fb.simulate(model="fem", settings={"FEM/Element size": 0.5}, progress=progress)')


def seconds_to_stop_after_sigint(script, *args):
    """Runs `script` in a fresh interpreter, sends SIGINT once it printed "running" (its first
    progress line) and returns the seconds it says it took to stop with KeyboardInterrupt."""
    import signal
    import subprocess
    import sys
    import time
    p = subprocess.Popen([sys.executable, "-c", script, *args], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    try:
        assert p.stdout.readline().strip() == "running"
        time.sleep(0.5)
        p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=30)
    finally:
        if p.poll() is None:
            p.kill()
    assert p.returncode == 3, (out, err)
    assert out.startswith("interrupted after"), (out, err)
    return float(out.split()[2])


def test_ctrl_c_stops_a_long_call():
    assert seconds_to_stop_after_sigint(INTERRUPTED) < 15


# run_scene sees Ctrl-C at every progress line of the scene too (items, models, nested scenes),
# not only when the scene returns: the same FEM run as a scene. The run directory keeps the
# marker of an incomplete run and gets no summary.json (app/outputs/run_directory.h).
INTERRUPTED_SCENE = interrupted_script(
    'fb.run_scene("prm/control_pva.prm", set={"Run": "fem", "FEM/Element size": 0.5, '
    '"Output directory": sys.argv[1]}, progress=progress)')


def test_ctrl_c_stops_a_long_scene(tmp_path):
    out = tmp_path / "out"
    # The whole run takes about a minute; the stop comes at the next progress line.
    assert seconds_to_stop_after_sigint(INTERRUPTED_SCENE, str(out)) < 15
    assert (out / "RUN_INCOMPLETE.txt").exists()
    assert not (out / "summary.json").exists()


def test_a_stop_in_scene_progress_is_not_a_failed_case(fb, tmp_path):
    # The study takes a failed stability case for a row of its table (it catches the model's
    # errors); a stop asked by the progress callback must end the whole run instead.
    seen = []

    def stop_at_the_first_stability_case(line):
        seen.append(line)
        if line.startswith("study: stability"):
            raise Stop(line)

    out = tmp_path / "out"
    with pytest.raises(Stop, match="study: stability"):
        fb.run_scene("prm/study_beam.prm", set={"Output directory": str(out),
                                                "Study/Beam ladder": "Number of elements = 50"},
                     progress=stop_at_the_first_stability_case)
    assert seen[0] == "fiberbridge: running study"
    assert (out / "RUN_INCOMPLETE.txt").exists()
    assert not (out / "summary.json").exists()
    # The module is usable after the unwound run.
    assert fb.simulate(model="beam").reached_steady_state


def test_numpy_scalars_are_settings_as_python_numbers_are(fb):
    # A lab's loop hands over numpy scalars (np.float64 from an array, np.bool_ from a mask): they
    # are the .prm text of the Python value they hold ("true", not numpy's "True").
    assert fb._value(np.bool_(True)) == "true"
    assert fb._value(np.float64(0.1)) == "0.1"
    assert fb._value(np.int64(100)) == "100"
    a = fb.simulate(model="beam", width_mm=np.float64(20.0),
                    settings={"Beam/Number of elements": np.int64(100)})
    b = fb.simulate(model="beam", width_mm=20.0, settings={"Beam/Number of elements": 100})
    assert a.G_ss_J_m2 == b.G_ss_J_m2
