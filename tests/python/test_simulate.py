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
