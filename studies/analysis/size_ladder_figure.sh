#!/usr/bin/env bash
# The size ladder as a figure (docs/STUDIES.md section 5): (a) v50 of break-up against N, both walls, with the
# 95 % intervals of the adaptive search and each wall's fit v50 = a N^b, the mobility diameter on the top axis;
# (b) E50/(N_c E_break) against N with the thresholds of Dominik & Tielens (1997). The numbers are size_ladder.py's
# (its --csv output); a group whose search is still under way is drawn with an open symbol.
#   studies/analysis/size_ladder_figure.sh runs/size_ladder_n32.sqlite runs/size_ladder_n128.sqlite ...
# Writes docs/figures/size_ladder.png (OUT=file.png elsewhere). Env AEROBREAK: the program that serves each store
# for the energy fit (build/aerobreak by default). Installs gnuplot-nox (apt-get) if missing.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
output=${OUT:-$root/docs/figures/size_ladder.png}
if [[ $# -lt 1 ]]; then
  sed -n '2,8s/^# \{0,1\}//p' "$0" >&2
  exit 2
fi
source "$root/docs/validation/gnuplot_support.sh"
ensure_gnuplot

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
table=$work/ladder.csv
python3 "$here/size_ladder.py" --csv "$table" "$@"

# Per wall ("adhesive", "none"): its fit's legend text and gnuplot's a and b, and whether a searching group is in
# it; the sizes with their mobility diameters (top axis); the ranges. Columns as size_ladder.py's CSV_COLUMNS.
facts=$(awk -F, 'NR > 1 {
    w = $2; walls[w] = 1; n[$1] = $15; if ($4 == "searching") { searching[w] = 1; any_searching = 1 }
    if ($17 != "") { a[w] = $16; b[w] = $17; text[w] = sprintf("%.3f [%.3f, %.3f], %d sizes", $17, $18, $19, $20) }
    if ($5 != "" && $5 > 0) { if (vmax == "" || $7 > vmax) vmax = $7; if (vmin == "" || $6 < vmin) vmin = $6 }
    if ($13 != "" && $13 > emax) emax = $13
    if (nmin == "" || $1 + 0 < nmin) nmin = $1 + 0; if ($1 + 0 > nmax) nmax = $1 + 0; d = $15 / $14 }
  END {
    for (w in walls) printf "searching_%s = %d\n", w, searching[w] + 0
    for (w in a) printf "a_%s = %s; b_%s = %s; fit_%s = \"%s\"\n", w, a[w], w, b[w], w, text[w]
    tics = ""; for (k in n) tics = tics sprintf("%s\047%.0f\047 %s", tics == "" ? "" : ", ", n[k], k)
    printf "d_tics = \"(%s)\"; n_tics = \"(", tics; first = 1
    for (k in n) { printf "%s%s", first ? "" : ", ", k; first = 0 }
    printf ")\"\nnmin = %s; nmax = %s; vmin = %s; vmax = %s; emax = %s; primary_nm = %.0f; any_searching = %d\n",
      nmin, nmax, vmin, vmax, emax + 0, d, any_searching + 0 }' "$table")

# Gnuplot's plot clauses of one quantity, its estimate and 95 % bounds in CSV columns $1, $2 and $3: per wall,
# the finished searches (converged or budget spent) filled, those under way open; each clause ends ", \" for the
# clauses that follow.
wall_points() {
  local wall final point colour title
  while read -r wall final point colour title; do
    printf '"%s" skip 1 using (shift($1, strcol(2))):(pick($%s, %s, %s)):%s:%s with yerrorbars pt %s ps 1.5 \\\n' \
      "$table" "$1" "$wall" "$final" "$2" "$3" "$point"
    printf '  lc rgb %s title %s, \\\n' "$colour" "$title"
  done <<'SERIES'
1 1 7 blue "adhesive wall"
0 1 5 red "wall without adhesion"
1 0 6 blue (searching_adhesive ? "adhesive, search under way" : "")
0 0 4 red (searching_none ? "no adhesion, search under way" : "")
SERIES
}

gnuplot <<GNUPLOT
a_adhesive = NaN; b_adhesive = 0; fit_adhesive = ""; searching_adhesive = 0
a_none = NaN; b_none = 0; fit_none = ""; searching_none = 0
$facts
set terminal $png_terminal size 1280,800 enhanced font "DejaVu Sans,12" linewidth 1.5
set output "$output"
set encoding utf8
set datafile separator ","
blue = "#1f77b4"; red = "#d62728"; grey = "#505050"
adhesive(w) = w eq "adhesive"
final(s) = s ne "searching"
# points of one wall shifted 4 % apart in N, so that overlapping intervals stay readable
shift(n, w) = n * (adhesive(w) ? 1 / 1.04 : 1.04)
pick(y, want_wall, want_final) = (adhesive(strcol(2)) == want_wall && final(strcol(4)) == want_final) ? y : NaN
power(n, a, b) = (n >= nmin && n <= nmax) ? a * n**b : NaN
set grid lc rgb "#dddddd" lw 1
set border lw 1.2
set key below Left reverse box samplen 2.5 spacing 1.1 font ",11" maxrows 3
set logscale x
set xrange [nmin / 1.6 : nmax * 1.6]
set xtics @n_tics
set x2range [nmin / 1.6 : nmax * 1.6]
set logscale x2
set x2tics @d_tics
set xlabel "N, primaries per cluster"
set x2label sprintf("mobility diameter d_{mob} = d N^{0.463} (nm), d = %.0f nm", primary_nm)
set bars 1.5
heading = sprintf("Size ladder: relaxed ballistic clusters of %.0f nm primaries hitting a wall head-on", primary_nm)
pooled = "each point: one N, one wall, all cases of that adaptive search; bars: 95 % intervals; "
note = any_searching ? "\nopen symbol: provisional, search still under way" : ""
set multiplot layout 1,2 title heading."\n".pooled."points 4 % apart in N".note font ",13"
provisional(wall_searching) = wall_searching ? " incl. provisional" : ""
# both panels the same size, whatever their keys (below each) hold
set tmargin at screen 0.78; set bmargin at screen 0.26

set lmargin at screen 0.07; set rmargin at screen 0.47
set title "(a) speed of 50 % break-up".(fit_adhesive.fit_none eq "" ? "" : "; lines: v_{50} = a N^b fitted per wall")
set logscale y
set yrange [vmin / 1.3 : vmax * 1.3]
set ytics (5, 7, 10, 15, 20, 30, 40, 50, 70, 100)
set ylabel "v_{50} (m/s)"
plot $(wall_points 5 6 7)
     power(x, a_adhesive, b_adhesive) with lines lc rgb blue dt 1 lw 1 \
       title (fit_adhesive eq "" ? "" : "fit, adhesive: b = ".fit_adhesive.provisional(searching_adhesive)), \
     power(x, a_none, b_none) with lines lc rgb red dt 4 lw 1 \
       title (fit_none eq "" ? "" : "fit, no adhesion: b = ".fit_none.provisional(searching_none))

set lmargin at screen 0.57; set rmargin at screen 0.97
set title "(b) energy per contact at 50 % break-up, E_{50}/(N_c E_{break})"
unset logscale y
set yrange [0 : (emax > 11 ? emax * 1.1 : 12)]
set ytics auto
set ylabel "E_{50} / (N_c E_{break})"
plot $(wall_points 11 12 13)
     10 with lines lc rgb grey dt 2 lw 1.5 title 'catastrophic disruption, 10 (Dominik \& Tielens 1997)', \
     3 with lines lc rgb grey dt 3 lw 2 title 'monomer loss, 3 (Dominik \& Tielens 1997)'
unset multiplot
GNUPLOT
ls -l "$output"
