#!/usr/bin/env bash
# Makes the bundled synthetic campaign (data/campaign_synthetic, issue 33 item 8): for every
# (material, cycles) of the seed's Table 1 (data/reference/seed_table1.csv), REPLICATES specimens,
# each an R(delta) file written by `fiberbridge synth` from the group's trilinear law
# (d1 = 0.1 mm, d2 = 1.0 mm, delta_c = 6.0 mm for PVA and 3.5 mm for the others, J_tip 200 J/m^2)
# with the specimen's own sigma1 and sigma2: the group's times 1 + CV z, z standard normal from a
# Park-Miller generator (exact in awk's doubles) clipped to [-2.5, 2.5]. synth adds its own 2 %
# J_tip scatter and R noise. Deterministic: the same files on every machine.
#
# Usage: scripts/make_synthetic_campaign.sh BUILD_DIR [OUT_DIR] [REPLICATES] [CV] [NOISE] [SEED]
set -euo pipefail
build=$(cd "${1:?usage: $0 BUILD_DIR [OUT_DIR] [REPLICATES] [CV] [NOISE_J_m2] [SEED]}" && pwd)
here=$(cd "$(dirname "$0")/.." && pwd)
out=${2:-$here/data/campaign_synthetic}
reps=${3:-5}
cv=${4:-0.10}
noise=${5:-4}
seed=${6:-20260}
mkdir -p "$out"
manifest="$out/manifest.csv"
{
  echo "# Synthetic campaign (NOT measured data): made by scripts/make_synthetic_campaign.sh with"
  echo "# fiberbridge synth from the seed's Table 1 laws; $reps specimens per group, specimen scatter"
  echo "# CV $cv on sigma1 and sigma2, R noise $noise J/m^2, seed $seed. See README.md."
  echo "file,material,cycles,specimen,delta_c_mm"
} > "$manifest.partial"
# One line per specimen: material cycles k s1 s2 dc synth-seed (awk draws the factors).
awk -F, -v reps="$reps" -v cv="$cv" -v seed="$seed" '
  function next_u() { x = (16807 * x) % 2147483647; return x / 2147483647 }
  function normal(   u1, u2) { u1 = next_u(); u2 = next_u(); if (u1 < 1e-12) u1 = 1e-12;
                               return sqrt(-2 * log(u1)) * cos(6.283185307179586 * u2) }
  function clip(z) { return z > 2.5 ? 2.5 : (z < -2.5 ? -2.5 : z) }
  BEGIN { x = seed }
  /^#/ { next }
  $1 == "material" { for (i = 3; i <= NF; ++i) if ($i ~ /^c[0-9]+$/) cyc[i] = substr($i, 2); next }
  $2 == "sigma1" { for (i in cyc) s1[$1, cyc[i]] = $i; mats[$1] = 1; order[++n] = $1 }
  $2 == "sigma2" { for (i in cyc) s2[$1, cyc[i]] = $i }
  END {
    nc = 0; for (i in cyc) cl[++nc] = cyc[i] + 0
    for (a = 1; a <= nc; ++a) for (b = a + 1; b <= nc; ++b) if (cl[b] < cl[a]) { t = cl[a]; cl[a] = cl[b]; cl[b] = t }
    for (m = 1; m <= n; ++m) {
      mat = order[m]; dc = (mat == "PVA") ? 6.0 : 3.5
      for (c = 1; c <= nc; ++c)
        for (k = 1; k <= reps; ++k) {
          f1 = 1 + cv * clip(normal()); f2 = 1 + cv * clip(normal())
          printf "%s %d %d %.6g %.6g %.1f %d\n", mat, cl[c], k, s1[mat, cl[c]] * f1, s2[mat, cl[c]] * f2, dc, int(next_u() * 1000000)
        }
    }
  }' "$here/data/reference/seed_table1.csv" |
while read -r mat cyc k s1 s2 dc sseed; do
  file="${mat}_c${cyc}_s${k}.csv"
  dmax=$(awk -v d="$dc" 'BEGIN { printf "%.3f", 1.5 * d }')
  # Run inside the folder so that the files' "regenerate with" line names no machine's path.
  (cd "$out" && "$build/fiberbridge" synth --out "$file" --type trilinear --points "0.1:$s1, 1.0:$s2" \
    --delta-c "$dc" --j-tip 200 --replicates 1 --rows 150 --noise "$noise" --delta-max "$dmax" \
    --seed "$sseed" > /dev/null)
  echo "$file,$mat,$cyc,s$k,$dc" >> "$manifest.partial"
done
mv "$manifest.partial" "$manifest"
echo "wrote $(($(wc -l < "$manifest") - 4)) specimens and $manifest"
