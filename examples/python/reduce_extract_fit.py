#!/usr/bin/env python3
"""A lab's own script: the four shared DCB records reduced to R(a), the bundled R(delta) sample
extracted to the bridging law (Eq. 5/6 beside sigma = dR/ddelta) and fitted, the fitted law put
back in the beam model, and R(a) plotted with matplotlib when it is installed. Run from the
repository root with the build tree's package:

    PYTHONPATH=build/python /usr/bin/python3 examples/python/reduce_extract_fit.py
"""
import fiberbridge as fb

records = [f"data/dcb_records/DCB-0{k}_Toughness.csv" for k in (1, 2, 3, 5)]
columns = {"time_s": "Time", "opening_mm": "Disp", "load_N": "Force", "a_mm": "CrackExt"}
red = fb.reduce(records, columns=columns, width_mm=25, height_mm=5.4, length_mm=123,
                E_L_MPa=19300)
for r in red.records:
    m = r.methods
    print(f"{r.name}: a0 {r.a0_mm:.1f} mm, plateau energy {m['energy']['plateau_J_m2']:.0f}, "
          f"MBT {m['MBT']['plateau_J_m2']:.0f}, CBBM {m['CBBM']['plateau_J_m2']:.0f} J/m^2")

# The law needs R against the notch-root opening (Eq. 5/6), and the four shared records measured
# none (no delta_root column: data/dcb_records/README.md). So the law comes from the bundled
# R(delta) sample: synthetic replicates of the seed's PVA control law by its Eq. 2, with noise
# (data/sample_rdelta_pva_control.csv says how it was made).
# A record that did measure delta_root (a DIC record from fb.dic, a clip gauge) goes straight on:
# ext = fb.extract(fb.reduce(my_records, ...)), and fit_trilinear then corrects the law by
# simulating those records.
ext = fb.extract("data/sample_rdelta_pva_control.csv")
fit = fb.fit_trilinear(ext)
print(f"J_tip {ext.J_tip_J_m2:.0f} J/m^2, G_ss {ext.G_ss_J_m2:.0f} J/m^2, delta_c "
      f"{ext.delta_c_mm:.2f} mm; trilinear sigma1 {fit.sigma1_kPa:.0f} kPa, "
      f"sigma2 {fit.sigma2_kPa:.0f} kPa")
sim = fb.simulate(fit, model="beam")
print(f"the fitted law back in the beam: G_ss {sim.G_ss_J_m2:.0f} J/m^2 "
      f"({sim.steady_state_status})")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib is not installed: no plot (apt install python3-matplotlib)")
else:
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for r in red.records:
        # The direct-energy R with its band: on these step-wise readings the pointwise R swings
        # by hundreds of J/m^2 (docs/verification.md, "The shared real records"), the band says
        # how far one reading can be trusted.
        line, = ax[0].plot(r.a_mm, r.R_energy_J_m2, label=r.name)
        ax[0].fill_between(r.a_mm, r.R_energy_lo_J_m2, r.R_energy_hi_J_m2,
                           color=line.get_color(), alpha=0.15, linewidth=0)
    ax[0].set_xlabel("a (mm)")
    ax[0].set_ylabel("R, direct energy (J/m$^2$)")
    ax[0].legend()
    ax[1].plot(ext.delta_mm, ext.sigma_eq5_kPa, label="Eq. 5/6")
    ax[1].plot(ext.delta_mm, ext.sigma_dRdd_kPa, label="dR/d$\\delta$")
    ax[1].set_xlabel("$\\delta$ (mm)")
    ax[1].set_ylabel("$\\sigma$ (kPa)")
    ax[1].legend()
    fig.tight_layout()
    fig.savefig("reduce_extract_fit.png", dpi=120)
    print("wrote reduce_extract_fit.png")
