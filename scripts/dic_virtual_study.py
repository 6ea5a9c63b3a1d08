#!/usr/bin/env python3
"""The paper's whole method end to end on the FEM's virtual DIC test (issue 32, verification;
docs/verification.md, "DIC end to end on the virtual test").

For each DIC strain window W the FEM runs once with FEM/Virtual DIC (frames in VIC CSV, the machine
record, the truth, dic_scene.prm); for each strain threshold the generated scene runs
`dic, reduce, extract` as a user would (fiberbridge run dic_scene.prm --set ...). Printed:
  - the rule's tip against the FEM's two tips (truth: crack_tip_mm = traction-free tip, the root
    of the bridging zone; zone_front_mm = the cohesive front): mean, min and max of
    zone_front - a_DIC and of a_DIC - crack_tip over the frames whose rule tip has left the notch
    root, and the opening at the rule's tip the strain rule implies, threshold x W / 1.5
    (docs/dic_tip_rule.md);
  - delta_root by the extensometer against the truth's delta_root_mm (largest |difference|);
  - the law from the DIC-derived R(delta_root) through Eq. 6 (the scene's cohesive_law_eq5.csv),
    from the FEM's own record (the DIC record's rows with the truth's zone front and
    delta_root, the same reduce and extract) and from the FEM's own R_energy(delta_root) rows
    (rcurve_fem.csv, an extract scene with Delta c = the rows' last delta_root), all against
    the input law (J_tip given, 200 J/m^2, for every route): RMS over
    [0, 1.05 max(delta_c)] divided by the input's peak (analysis/law_routes.h's rms_rel).

Usage: scripts/dic_virtual_study.py [BUILD_DIR] [--case short|pva] [--out DIR]
Environment: DIC_STUDY_WINDOWS (mm, default 2,3,5), DIC_STUDY_THRESHOLDS (default 0.005,0.01,0.02),
DIC_STUDY_HALF_WIDTH (Eq. 6 slope half-width in grid intervals for every route, default 10),
DIC_STUDY_SMOOTHING (reduce's Test/Smoothing window in mm for both records, default 8).
Cases: short = the ctest's linear-softening DCB (1000 kPa, delta_c 0.4 mm, 120 mm, 1 mm elements,
0.5 mm points, seconds per run); pva = prm/fem_virtual_test_pva.prm's PVA law on the seed's DCB
(minutes per run).
"""
import csv, math, os, subprocess, sys

args = sys.argv[1:]
build = args.pop(0) if args and not args[0].startswith("--") else "build"
case, out = "short", None
while args:
    k = args.pop(0)
    if k == "--case":
        case = args.pop(0)
    elif k == "--out":
        out = args.pop(0)
    else:
        sys.exit("unknown argument " + k)
root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
exe = os.path.abspath(os.path.join(build, "fiberbridge"))
out = os.path.abspath(out or os.path.join("output", "dic_virtual_study_" + case))
windows = [float(v) for v in os.environ.get("DIC_STUDY_WINDOWS", "2,3,5").split(",")]
thresholds = [float(v) for v in os.environ.get("DIC_STUDY_THRESHOLDS", "0.005,0.01,0.02").split(",")]
half_width = int(os.environ.get("DIC_STUDY_HALF_WIDTH", "10"))
smoothing = float(os.environ.get("DIC_STUDY_SMOOTHING", "8"))

if case == "short":
    # tests/fem/dic_end_to_end_tests.cc's case (fem_test::short_dcb, the linear-softening law).
    # make_linear_softening(1000 kPa, 0.4 mm).with_elastic_rise(0.04 mm): 900 kPa at 0.04 mm.
    law_points = [(0.0, 0.0), (0.04, 900.0), (0.4, 0.0)]  # mm, kPa
    scene_head = """
subsection Specimen
  set Length = 120
  set Width = 20
  set Height = 20
  set Initial crack = 40
end
subsection Cohesive law
  set Type = trilinear
  set Points = 0.04:900, 0.22:450
  set Delta c = 0.4
  set J tip = 200
end
subsection FEM
  set Element size = 1
  set Steady state window = 20
  subsection Virtual DIC
    set Enabled = true
    set Format = vic
    set Frame rate = 50
    set Record rate = 200
    set Crosshead rate = 60
    set First frame time = 0.01
    set X from = 35
    set X to = 120
    set Y from = -6
    set Y to = 6
    set Point spacing = 0.5
    set Displacement noise = 0.0005
    set Seed = 7
    set Strain window = {window}
  end
end
"""
elif case == "pva":
    law_points = [(0.0, 0.0), (0.1, 661.0), (1.0, 187.0), (6.0, 0.0)]
    scene_head = """
subsection Cohesive law
  set Type = trilinear
  set Points = 0.1:661, 1.0:187
  set Delta c = 6
  set J tip = 200
end
subsection FEM
  set Element size = 2
  # Run on 30 mm past the steady-state onset (to the specimen's end): the extensometer's
  # R(delta_root) needs its plateau beyond delta_c for the automatic delta_c (the default 10 mm
  # leaves R still rising there).
  set Steady state window = 30
  subsection Virtual DIC
    set Enabled = true
    set Format = vic
    set Frame rate = 1
    set Crosshead rate = 10
    set X from = 90
    set X to = 300
    set Y from = -10
    set Y to = 10
    set Point spacing = 1
    set Displacement noise = 0.002
    set Strain window = {window}
  end
end
"""
else:
    sys.exit("--case short|pva")


def law_at(d):
    for (d0, s0), (d1, s1) in zip(law_points, law_points[1:]):
        if d0 <= d <= d1:
            return s0 + (s1 - s0) * (d - d0) / (d1 - d0)
    return 0.0


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(l for l in f if l.strip() and not l.startswith("#")))


def run(cmd, log):
    with open(log, "w") as f:
        r = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT)
    if r.returncode:
        sys.exit("failed (%d): %s; see %s" % (r.returncode, " ".join(cmd), log))


def law_rms(law_csv):
    """rms_rel of analysis/law_routes.h: RMS of (sigma - input) on 2001 points over
    [0, 1.05 max(delta_c of both)] (the extracted law zero beyond its grid) over the input's peak."""
    L = rows(law_csv)
    key = [k for k in L[0] if k.startswith("sigma")][0]
    d = [float(r["delta_mm"]) for r in L]
    s = [float(r[key]) for r in L]

    def ext(x):
        if x > d[-1]:
            return 0.0
        for i in range(1, len(d)):
            if x <= d[i]:
                return s[i - 1] + (s[i] - s[i - 1]) * (x - d[i - 1]) / (d[i] - d[i - 1])
        return 0.0

    top = 1.05 * max(d[-1], law_points[-1][0])
    n = 2001
    acc = sum((ext(top * i / (n - 1)) - law_at(top * i / (n - 1))) ** 2 for i in range(n))
    return math.sqrt(acc / n) / max(p[1] for p in law_points), d[-1]


def at_time(truth, t, key):
    for a, b in zip(truth, truth[1:]):
        ta, tb = float(a["time_s"]), float(b["time_s"])
        if ta <= t <= tb:
            w = (t - ta) / (tb - ta) if tb > ta else 0
            return (1 - w) * float(a[key]) + w * float(b[key])
    return float(truth[-1][key]) if t > float(truth[-1]["time_s"]) else float(truth[0][key])


os.makedirs(out, exist_ok=True)
a0 = 40.0 if case == "short" else None
j_tip = 200
common = ["--set", "Data/Smoothing half-width=%d" % half_width, "--set", "Data/J tip=%g" % j_tip,
          "--set", "Test/Smoothing window=%g" % smoothing]
stat = lambda v: "%+.2f [%+.2f, %+.2f]" % (sum(v) / len(v), min(v), max(v)) if v else "-"
print("| W mm | threshold | thr x W / 1.5 um | rows | a_DIC - zone_front mm, mean [min, max] | "
      "a_DIC - crack_tip mm, mean [min, max] | delta_root max abs err um (front > a0 + 2 mm) | "
      "Eq. 6 RMS DIC | Eq. 6 RMS FEM record | Eq. 6 RMS FEM rows | delta_c DIC mm |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for W in windows:
    fdir = os.path.join(out, "fem_W%g" % W)
    scene = os.path.join(out, "fem_W%g.prm" % W)
    with open(scene, "w") as f:
        f.write("set Output directory = %s\nset Run = fem\n" % fdir)
        f.write(scene_head.format(window=W))
    run([exe, "run", scene], scene + ".log")
    vt = os.path.join(fdir, "virtual_test")
    dic_scene = os.path.join(vt, "dic_scene.prm")
    truth = rows(os.path.join(vt, "virtual_test_truth.csv"))
    if a0 is None:
        a0 = float(truth[0]["crack_tip_mm"])
    # Route 1, the FEM's own rows: R_energy(delta_root) per advance (delta_root increasing; they
    # stop at delta_c, which extract is given).
    own = os.path.join(fdir, "rdelta_own.csv")
    last = 0.0
    with open(own, "w") as f:
        f.write("delta_mm,R_J_m2\n")
        for r in rows(os.path.join(fdir, "rcurve_fem.csv")):
            if r["R_energy_J_m2"] and float(r["delta_root_mm"]) > last:
                last = float(r["delta_root_mm"])
                f.write("%s,%s\n" % (r["delta_root_mm"], r["R_energy_J_m2"]))
    edir = os.path.join(fdir, "extract_own")
    escene = os.path.join(fdir, "extract_own.prm")
    with open(escene, "w") as f:
        f.write("set Output directory = %s\nset Run = extract\n" % edir)
        f.write("subsection Data\n  set File = %s\n  set Delta c = %.6g\n  set J tip = %g\n"
                "  set Smoothing half-width = %d\nend\n" % (own, last, j_tip, half_width))
    run([exe, "run", escene], escene + ".log")
    rows_rms, _ = law_rms(os.path.join(edir, "cohesive_law_eq5.csv"))
    rec_rms = None
    for thr in thresholds:
        ddir = os.path.join(fdir, "dic_t%g" % thr)
        run([exe, "run", dic_scene, "--set", "Output directory=" + ddir,
             "--set", "DIC/Strain threshold=%g" % thr] + common, ddir + ".log")
        rec = rows(os.path.join(ddir, "dic_record.csv"))
        if rec_rms is None:
            # Route 2, the FEM's own record: the DIC record's rows with the truth's zone front
            # and delta_root, through the same reduce and extract.
            own_rec = os.path.join(fdir, "fem_own_record.csv")
            with open(own_rec, "w") as f:
                f.write("time_s,opening_mm,load_N,a_mm,delta_root_mm\n")
                for r in rec:
                    t = float(r["time_s"])
                    f.write("%s,%s,%s,%.9g,%.9g\n" % (r["time_s"], r["opening_mm"], r["load_N"],
                            at_time(truth, t, "zone_front_mm"), at_time(truth, t, "delta_root_mm")))
            odir = os.path.join(fdir, "fem_own_record")
            run([exe, "run", dic_scene, "--set", "Output directory=" + odir, "--set",
                 "Run=reduce, extract", "--set", "Test/Files=" + own_rec] + common, odir + ".log")
            rec_rms, _ = law_rms(os.path.join(odir, "cohesive_law_eq5.csv"))
        lag, ahead, err = [], [], []
        for r in rec:
            t, a = float(r["time_s"]), float(r["a_mm"])
            if at_time(truth, t, "zone_front_mm") >= a0 + 2:
                err.append(abs(float(r["delta_root_mm"]) - at_time(truth, t, "delta_root_mm")) * 1e3)
            if a > a0 + 1e-9:
                lag.append(a - at_time(truth, t, "zone_front_mm"))
                ahead.append(a - at_time(truth, t, "crack_tip_mm"))
        dic_rms, dc = law_rms(os.path.join(ddir, "cohesive_law_eq5.csv"))
        print("| %g | %g | %.1f | %d | %s | %s | %.2f | %.3f | %.3f | %.3f | %.3f |" % (
            W, thr, thr * W / 1.5 * 1e3, len(rec), stat(lag), stat(ahead), max(err) if err else -1,
            dic_rms, rec_rms, rows_rms, dc), flush=True)
