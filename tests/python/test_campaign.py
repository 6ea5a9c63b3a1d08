"""campaign against the bundled campaign scene (the same groups, intervals, degradation and
ranking, number for number), and its input errors."""
import pytest

from conftest import read_summary, run_cli

MANIFEST = "data/campaign_synthetic/manifest.csv"
SETTINGS = {"Campaign/Bootstrap samples": 1000, "Campaign/Seed": 1,
            "Campaign/Reference materials": "DF"}


def test_campaign_gives_the_scene_s_table_and_ranking(fb, out):
    run_cli("run", "prm/campaign_table1.prm", "--set", f"Output directory={out}")
    scene = read_summary(out)["campaign"]
    c = fb.campaign(MANIFEST, settings=SETTINGS)
    # Everything but the wall time, the ranks and the manifest's path as the scene names it.
    for key in ("groups", "degradation", "ranking", "ranking_detail", "ranking_confidence",
                "n_specimens", "n_groups", "interval", "reference_materials", "not_ranked",
                "notes"):
        assert getattr(c, key) == scene[key], key
    assert c.ranking == scene["ranking"] and len(c.ranking) >= 3
    assert "groups estimated" in repr(c)


def test_a_missing_manifest_is_an_input_error_naming_it(fb):
    with pytest.raises(fb.InputError, match="no_manifest.csv"):
        fb.campaign("no_manifest.csv")


class Stop(Exception):
    pass


def test_progress_sees_each_group_and_can_stop_the_call(fb):
    # The campaign catches a group's failure as a row of its table; a stop asked by the progress
    # callback (or Ctrl-C, checked at the same lines) must end the call instead.
    seen = []

    def stop_at_the_third_group(line):
        seen.append(line)
        if len(seen) == 3:
            raise Stop(line)

    with pytest.raises(Stop, match="campaign: group 3/"):
        fb.campaign(MANIFEST, settings=SETTINGS, progress=stop_at_the_third_group)
    assert [s.split()[2] for s in seen] == ["1/20", "2/20", "3/20"]
    # The module is usable after the unwound call.
    assert len(fb.campaign(MANIFEST, settings=SETTINGS).groups) == 20
