#!/usr/bin/env bash
# The report's figure 4 (SAND2010-7105 section 3.3), reduced to 256 primaries: side views (x-z) of
# the impact of studies/figure4_impact_n256.case.json at four times, the wall grey at z = 0, far
# primaries dark (docs/IMPACT.md 6 and 7). Writes docs/figures/impact_figure4_n256.png.
#   docs/validation/impact_figure4.sh                      the reduced case, build/aerobreak
#   CASE=studies/figure4_impact.case.json OUT=impact_figure4.png docs/validation/impact_figure4.sh
#                                                          the full 4096-primary case (~30 min)
# Installs gnuplot-nox (apt-get) if missing.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
aerobreak=${AEROBREAK:-$root/build/aerobreak}
case_file=${CASE:-$root/studies/figure4_impact_n256.case.json}
output=$root/docs/figures/${OUT:-impact_figure4_n256.png}
source "$here/gnuplot_support.sh"
ensure_gnuplot

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$aerobreak" impact "$case_file" -q -o "$work/result.json" --xyz "$work/impact.xyz"
# one "x y z r" file per frame, and the frame times in frames.txt
(cd "$work" && awk 'left == 0 { left = $1; getline; t = $0; sub(/.*time=/, "", t); sub(/ .*/, "", t);
                 name = sprintf("frame_%d.dat", n); print n, t > "frames.txt"; n++; next }
     { print $2, $3, $4, $5 > name; left-- }' n=0 impact.xyz)
frames=$(wc -l < "$work/frames.txt")
picks="0 $((frames / 4)) $((frames / 2)) $((frames - 1))"
extent=$(awk '{ if ($1 > m) m = $1; if (-$1 > m) m = -$1; if ($3 > h) h = $3 } END { printf "%d %d", m + 4, h + 2 }' "$work"/frame_0.dat)

gnuplot <<GNUPLOT
set terminal $png_terminal size 1800,560 font ",12" noenhanced
set output "$output"
set multiplot layout 1,4 title "Side view (x-z) of a ballistic cluster hitting a wall without adhesion ($(basename "$case_file"))"
set size ratio -1
unset key; unset colorbox
set xrange [-$(echo $extent | cut -d' ' -f1):$(echo $extent | cut -d' ' -f1)]; set yrange [-1.5:$(echo $extent | cut -d' ' -f2)]
set xlabel "x / d"; set ylabel "z / d"
set palette defined (0 "#2b4c8c", 1 "#d8e2f4")
set object 1 rectangle from -1000,-2 to 1000,0 fillcolor rgb "#909090" fillstyle solid behind
do for [f in "$picks"] {
  t = system("awk '\$1 == ".f." {print \$2}' $work/frames.txt")
  set title sprintf("t = %.0f τ", t + 0)
  plot sprintf("< sort -g -r -k2 $work/frame_%s.dat", f) using 1:3:4:(-\$2) \
       with circles fillstyle solid 1.0 border lc rgb "#202020" lc palette
}
unset multiplot
GNUPLOT
python3 -c "import json, sys; o = json.load(open(sys.argv[1]))['outcome']
print('outcome', o['class'], 'e_n', round(o['restitution']['normal'], 3), 'fragments', o['fragment_count'])" "$work/result.json"
ls -l "$output"
