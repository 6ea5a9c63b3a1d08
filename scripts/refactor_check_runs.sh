#!/bin/bash
# The runs of a refactor's output check (docs/verification.md, issue 40): the bundled scenes that
# exercise every item, resume and the MPI task hand-out, run by BINARY into OUTROOT/<run>. Run it
# with the binary before and after a change, then compare the two folders:
#   bash scripts/refactor_check_runs.sh /tmp/fb_before /tmp/cmp/before
#   bash scripts/refactor_check_runs.sh build/fiberbridge /tmp/cmp/after
#   python3 scripts/compare_outputs.py /tmp/cmp/before /tmp/cmp/after
# About 15 minutes on 2 cores (the chain study and identify dominate). From the repository root.
source "$(dirname "$0")/check_runs_common.sh"
run default prm/default.prm
run campaign_table1 prm/campaign_table1.prm
run campaign_real_records prm/campaign_real_records.prm
run study_beam prm/study_beam.prm
run test_records prm/test_records.prm --set "Run=reduce, identify"
run fem_virtual prm/fem_virtual_test_pva.prm
run chain prm/study_chain.prm --set "Chain study/Table 1=data/reference/seed_table1.csv"
# --resume: a second run into the default scene's folder restores every simulation.
cp -r "$root/default" "$root/default_resumed"
"$bin" run prm/default.prm --resume --set "Output directory=$root/default_resumed" \
  >"$root/default_resumed.log" 2>&1
echo "default_resumed rc=$?"
# The MPI task hand-out: the default scene's simulations as tasks over 2 ranks.
mpirun --allow-run-as-root --oversubscribe -np 2 "$bin" run prm/default.prm \
  --set "Output directory=$root/default_mpi" >"$root/default_mpi.log" 2>&1
echo "default_mpi rc=$?"
