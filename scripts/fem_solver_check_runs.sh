#!/bin/bash
# The runs of an FEM solver change's output check (docs/verification.md, "One Newton"): every
# nonlinear path of the engine (full, crack-plane and bordered Newton, KINSOL, finite kinematics,
# 3D, two MPI ranks), run by BINARY into OUTROOT/<run>. Run it with the binary before and after
# a change, then compare the two folders as scripts/refactor_check_runs.sh says:
#   bash scripts/fem_solver_check_runs.sh /tmp/fb_before /tmp/cmp/before
#   bash scripts/fem_solver_check_runs.sh build/fiberbridge /tmp/cmp/after
#   python3 scripts/compare_outputs.py /tmp/cmp/before /tmp/cmp/after
# Two MPI ranks may differ in a last digit between two runs of one binary (the order of the
# reductions). About 2 minutes on 2 cores (3D: 1 minute). From the repository root.
source "$(dirname "$0")/check_runs_common.sh"
# A law strong and short enough to switch to the crack-tip opening control (bordered Newton).
snap=(--set "Cohesive law/Type=linear" --set "Cohesive law/Peak stress=30000"
  --set "Cohesive law/Delta c=0.02" --set "Cohesive law/J tip=100")
run seed_pva prm/control_pva.prm --set Run=fem
run snap_2mm prm/control_pva.prm --set Run=fem "${snap[@]}" --set "FEM/Element size=2"
run snap_auto prm/control_pva.prm --set Run=fem "${snap[@]}"
run thin_epi prm/fem_thin_epi.prm
run lefm_thin prm/lefm_thin_composite.prm --set Run=fem --set Specimen/Height=3
run kinsol_pva prm/control_pva.prm --set Run=fem --set "FEM/Nonlinear solver=kinsol"
run finite_thin prm/lefm_thin_composite.prm --set Run=fem --set Specimen/Height=2 \
  --set "FEM/Kinematics=finite"
run default prm/default.prm
run fem3d prm/fem3d_pva_control.prm
mpirun --allow-run-as-root --oversubscribe -np 2 "$bin" run prm/fem_mpi_pva_control.prm \
  --set "Output directory=$root/mpi2" >"$root/mpi2.log" 2>&1
echo "mpi2 rc=$?"
