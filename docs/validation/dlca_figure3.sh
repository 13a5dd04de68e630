#!/usr/bin/env bash
# The report's figure 3 (SAND2010-7105 section 3.2): clusters grown by diffusion-limited
# cluster-cluster aggregation in the engine, (a) without sintering (rolling and twisting free: the
# clusters fold up) and (b) with the report's sintering constraints (they keep their open shape).
# Writes docs/figures/dlca_figure3.png: each cluster seen from two sides, with its Rg and contacts.
#   docs/validation/dlca_figure3.sh               N = 32, seed 1, build/aerobreak
#   N=64 SEED=2 AEROBREAK=/path/aerobreak docs/validation/dlca_figure3.sh
# Installs gnuplot-nox (apt-get) if missing. Cost: docs/VALIDATION.md 8.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
aerobreak=${AEROBREAK:-$root/build/aerobreak}
primaries=${N:-32}
seed=${SEED:-1}
source "$here/gnuplot_support.sh"
ensure_gnuplot

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for mode in no-sintering sintering; do
  start=$(date +%s.%N)
  "$aerobreak" cluster generate --generator dlca "--$mode" --primaries "$primaries" --seed "$seed" \
    --output "$work/$mode.xyz" >/dev/null
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  rg=$(radius_of_gyration "$work/$mode.xyz")
  contacts=$(contact_count "$work/$mode.xyz")
  echo "$mode: N = $primaries, seed $seed, Rg = $rg d, $contacts contacts, generated in $seconds s"
  echo "$rg $contacts" > "$work/$mode.txt"
done

gnuplot <<GNUPLOT
set terminal $png_terminal size 1400,760 font ",12" noenhanced
set output "$root/docs/figures/dlca_figure3.png"
set multiplot layout 2,2 title "DLCA clusters of $primaries primaries grown in the engine (seed $seed): (a) without sintering, (b) with sintering"
set size ratio -1
unset key; unset colorbox
set palette defined (0 "#2b4c8c", 1 "#d8e2f4")
set xrange [-9:9]; set yrange [-7:7]
do for [view in "xz yz"] {
  do for [mode in "no-sintering sintering"] {
    stats = system("cat $work/".mode.".txt")
    label = (mode eq "sintering") ? "(b) sintered" : "(a) not sintered"
    set title sprintf("%s, view %s: Rg = %s d, %s contacts", label, view, word(stats, 1), word(stats, 2))
    set xlabel (view eq "xz") ? "x / d" : "y / d"; set ylabel "z / d"
    # centred on the centre of mass; far primaries (larger depth) drawn first and darker
    cmd = sprintf("< awk '!/^#/ {n++; x[n]=\$1; y[n]=\$2; z[n]=\$3; r[n]=\$4; sx+=\$1; sy+=\$2; sz+=\$3} END {for (i=1;i<=n;i++) print (\"%s\"==\"xz\" ? x[i]-sx/n : y[i]-sy/n), z[i]-sz/n, r[i], (\"%s\"==\"xz\" ? y[i]-sy/n : -(x[i]-sx/n))}' $work/%s.xyz | sort -g -r -k4", view, view, mode)
    plot cmd using 1:2:3:(-\$4) with circles fillstyle solid 1.0 border lc rgb "#202020" lc palette
  }
}
unset multiplot
GNUPLOT
ls -l "$root/docs/figures/dlca_figure3.png"
