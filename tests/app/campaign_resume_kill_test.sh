#!/bin/bash
# A campaign killed mid-run (SIGKILL, as a cluster job past its wall time) and continued with
# --resume into the same output directory gives the straight run's campaign_table1.csv byte for
# byte (issue 33 item 6). The kill comes once two groups are kept (resume/campaign_group_*.bin);
# a run that finishes before it can be killed leaves nothing to test: exit 77 (skipped).
# Usage: campaign_resume_kill_test.sh FIBERBRIDGE SOURCE_DIR WORK_DIR
set -u
bin=$1 src=$2 work=$3
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
scene="$src/prm/campaign_table1.prm"
args=(--set "Campaign/Bootstrap samples=1000")
"$bin" run "$scene" --set "Output directory=$work/straight" "${args[@]}" > "$work/straight.log" 2>&1 \
  || { cat "$work/straight.log"; fail "straight run"; }
"$bin" run "$scene" --set "Output directory=$work/killed" "${args[@]}" > "$work/killed.log" 2>&1 &
pid=$!
for _ in $(seq 1 6000); do
  n=$(ls "$work/killed/resume"/campaign_group_*.bin 2>/dev/null | wc -l)
  [ "$n" -ge 2 ] && break
  kill -0 $pid 2>/dev/null || break
  sleep 0.01
done
kill -KILL $pid 2>/dev/null
wait $pid 2>/dev/null
if [ -f "$work/killed/campaign_table1.csv" ]; then
  echo "the run finished before it could be killed: nothing to test"; exit 77
fi
kept=$(ls "$work/killed/resume"/campaign_group_*.bin 2>/dev/null | wc -l)
[ "$kept" -ge 1 ] || fail "no group kept before the kill"
"$bin" run "$scene" --set "Output directory=$work/killed" "${args[@]}" --resume > "$work/resumed.log" 2>&1 \
  || { cat "$work/resumed.log"; fail "resumed run"; }
restored=$(grep -c 'campaign: resume: group' "$work/resumed.log")
[ "$restored" = "$kept" ] || fail "$kept groups kept, $restored restored"
for f in campaign_table1.csv campaign_groups.csv campaign_degradation.csv campaign_ranking_confidence.csv; do
  cmp -s "$work/straight/$f" "$work/killed/$f" || { diff "$work/straight/$f" "$work/killed/$f" | head; fail "$f differs"; }
done
echo "campaign killed after $kept of 20 groups and resumed: the straight run's tables"
