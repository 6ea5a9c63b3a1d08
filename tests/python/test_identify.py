"""identify against a scene's identify (the same doubles) on a CI-sized fit: one shared record,
one optimizer start, few evaluations on a coarse beam (tests/app/scenes/identify_mpi_small.prm's
settings). Not a converged identification: tests/identify checks the fit itself."""
import os

import pytest

from conftest import COLUMNS, SPECIMEN, read_summary, run_cli

RECORD = "data/dcb_records/DCB-05_Toughness.csv"
SMALL = {"Identify/Starts": 1, "Identify/Max evaluations": 30, "Identify/Tolerance": 1e-3,
         "Identify/Number of elements": 40, "Identify/Tip advance": 2}


def test_identify_gives_the_scene_s_law(fb, tmp_path):
    out = tmp_path / "out"
    sets = [f"Test/Files={os.path.abspath(RECORD)}",
            "Test/Columns=" + ", ".join(f"{k}: {v}" for k, v in COLUMNS.items())]
    sets += [f"Specimen/{k}={v}" for k, v in (("Width", 25), ("Height", 5.4), ("Length", 123))]
    sets += [f"Material/{k}={v}" for k, v in (("E_L", 19300), ("E_T", 6110), ("G_LT", 2288),
                                               ("nu_LT", 0.3))]
    sets += [f"{k}={v}" for k, v in SMALL.items()]
    scene = tmp_path / "scene.prm"
    scene.write_text("set Run = identify\n")
    args = ["run", str(scene), "--set", f"Output directory={out}"]
    for s in sets:
        args += ["--set", s]
    run_cli(*args)
    law = read_summary(out)["identify"]
    lines = []
    id_ = fb.identify(RECORD, columns=COLUMNS, settings=SMALL, progress=lines.append, **SPECIMEN)
    assert lines, "no progress line"
    tri = law["trilinear"]
    for ours, theirs in (("delta1_mm", "d1_mm"), ("sigma1_kPa", "sigma1_kPa"),
                         ("delta2_mm", "d2_mm"), ("sigma2_kPa", "sigma2_kPa"),
                         ("delta_c_mm", "delta_c_mm")):
        assert getattr(id_, ours) == tri[theirs], ours
    assert id_.J_tip_J_m2 == law["J_tip_J_m2"]
    assert id_.G_ss_J_m2 == law["G_ss_J_m2"]
    assert id_.evaluations == law["evaluations"]
    assert id_.records[0].name == law["records"][0]["record"]
    assert len(id_.records[0].model_load_N) == len(id_.records[0].load_N)
    # The identified law goes to simulate as a fitted one does.
    assert fb.simulate(id_.law, model="beam").reached_steady_state


def test_identify_names_a_missing_record(fb):
    with pytest.raises(fb.InputError, match="no_such_record.csv"):
        fb.identify("no_such_record.csv", columns=COLUMNS, settings=SMALL, **SPECIMEN)


class Stop(Exception):
    pass


def test_a_stop_inside_the_optimizer_is_raised_as_it_was(fb):
    # The optimizer's progress line comes from inside NLopt's objective (every 50 evaluations),
    # whose C++ wrapper turns any exception into "nlopt failure": the callback's own exception
    # (or KeyboardInterrupt from Ctrl-C) must come out as it was raised.
    def stop_inside(line):
        if "evaluations, best chi^2" in line:
            raise Stop(line)

    with pytest.raises(Stop, match="50 evaluations"):
        # A tolerance that keeps the optimizer going past 50 evaluations.
        fb.identify(RECORD, columns=COLUMNS,
                    settings={**SMALL, "Identify/Max evaluations": 120, "Identify/Tolerance": 1e-8},
                    progress=stop_inside, **SPECIMEN)
