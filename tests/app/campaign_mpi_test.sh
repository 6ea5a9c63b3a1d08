#!/bin/bash
# The campaign's groups as independent tasks across ranks (issue 33 item 6): the bundled
# synthetic campaign on one process and under `mpirun -np 2` gives the same tables (every
# column; the bootstrap of a group depends only on its specimens, the options and its own seed,
# and the samples cross ranks printed to round trip exactly), rank 1 writes nothing.
# Usage: campaign_mpi_test.sh MPIEXEC FIBERBRIDGE SOURCE_DIR WORK_DIR
set -u
mpiexec=$1 bin=$2 src=$3 work=$4
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
scene="$src/prm/campaign_table1.prm"
# The laws back in the specimen too (tasks of their own) when the build has the beam model.
sim=false
"$bin" parameters 2>/dev/null | grep -q "subsection Beam" && sim=true
"$bin" run "$scene" --set "Output directory=$work/c1" --set "Campaign/Bootstrap samples=100" --set "Campaign/Simulate laws=$sim" \
  > "$work/c1.log" 2>&1 || { cat "$work/c1.log"; fail "campaign on one process"; }
"$mpiexec" -np 2 --oversubscribe "$bin" run "$scene" --set "Output directory=$work/c2" \
  --set "Campaign/Bootstrap samples=100" --set "Campaign/Simulate laws=$sim" > "$work/c2.log" 2>&1 \
  || { cat "$work/c2.log"; fail "campaign on 2 ranks"; }
for f in campaign_table1.csv campaign_groups.csv campaign_degradation.csv \
         campaign_ranking_confidence.csv campaign_law_PVA_c0.csv campaign_specimens.csv \
         $([ $sim = true ] && echo campaign_fig10_PVA_c0.csv campaign_fig10_DF_c24.csv); do
  cmp -s "$work/c1/$f" "$work/c2/$f" || { diff "$work/c1/$f" "$work/c2/$f" | head; fail "$f differs"; }
done
# Resumed on 2 ranks (item 6): stopped after the PVA groups (their records only), continued with
# --resume: the restored and the recomputed groups give the one-process tables.
find "$work/c2" -mindepth 1 -maxdepth 1 ! -name resume -exec rm -rf {} +
find "$work/c2/resume" -type f ! -name '*_PVA_*' -delete
"$mpiexec" -np 2 --oversubscribe "$bin" run "$scene" --set "Output directory=$work/c2" \
  --set "Campaign/Bootstrap samples=100" --set "Campaign/Simulate laws=$sim" --resume \
  > "$work/c2r.log" 2>&1 || { cat "$work/c2r.log"; fail "campaign resumed on 2 ranks"; }
[ "$(grep -c 'campaign: resume: group' "$work/c2r.log")" = 4 ] || { cat "$work/c2r.log"; fail "4 PVA groups restored"; }
for f in campaign_table1.csv campaign_groups.csv campaign_law_PVA_c0.csv \
         $([ $sim = true ] && echo campaign_fig10_PVA_c0.csv campaign_fig10_DF_c24.csv); do
  cmp -s "$work/c1/$f" "$work/c2/$f" || { diff "$work/c1/$f" "$work/c2/$f" | head; fail "$f differs after --resume on 2 ranks"; }
done
python3 - "$work/c2/summary.json" <<'PY' || fail "summary"
import json, sys
s = json.load(open(sys.argv[1]))["campaign"]
assert s["ranks"] == 2, s["ranks"]
assert s["ranking"] == ["PF", "EPI", "PRF", "PVA"], s["ranking"]
PY
echo "campaign ok: the same tables on 1 and 2 ranks, and resumed on 2 ranks (laws simulated: $sim)"
