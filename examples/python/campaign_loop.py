#!/usr/bin/env python3
"""A campaign loop from Python: the bundled synthetic durability campaign (100 specimens over
five materials and four moisture-cycle counts, data/campaign_synthetic) analysed with two interval
rules, and each group's sigma1 with its two 95 % intervals side by side; then the ranking with
its confidence. fb.campaign computes what a scene's campaign computes and writes nothing.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/campaign_loop.py
"""
import fiberbridge as fb

manifest = "data/campaign_synthetic/manifest.csv"
runs = {}
for rule in ("student t", "percentile"):
    c = fb.campaign(manifest, settings={"Campaign/Interval": rule,
                                        "Campaign/Reference materials": "DF"})
    runs[rule] = {(g["material"], g["cycles"]): g for g in c.groups}
print(c)

for (material, cycles), g in sorted(runs["student t"].items()):
    if not g["ok"]:
        print(f"{material:>4} {cycles:>3g} cycles: not estimated ({'; '.join(g['notes'])})")
        continue
    t = g["ci"]["sigma1_kPa"]
    p = runs["percentile"][(material, cycles)]["ci"]["sigma1_kPa"]
    print(f"{material:>4} {cycles:>3g} cycles: sigma1 {g['trilinear']['sigma1_kPa']:.0f} kPa, "
          f"student t [{t[0]:.0f}, {t[1]:.0f}], percentile [{p[0]:.0f}, {p[1]:.0f}]")
for pair in c.ranking_confidence:
    print(f"P({pair['first']} ahead of {pair['second']}) = {pair['p_first_ahead']:.2f}")
