# Energy budget of a relaxed 64-primary BCCA cluster hitting an adhesive wall head-on at 0.5 d/tau with
# the full contact model, and the closure error of the ledger.
load here."/common.gnuplot"
file = data."/energy.csv"
set output out."/energy_budget.png"
stats file skip 1 using ($1 == 0 ? $3 : NaN) nooutput
E0 = STATS_max
stats file skip 1 using 2 nooutput
t_end = STATS_max
stats file skip 1 every ::1::1 using 1 nooutput
every = int(STATS_max)
stats file skip 1 every ::1::1 using ($2 / $1) nooutput
dt = STATS_max

set multiplot
set lmargin 11; set rmargin 3
set size 1, 0.7; set origin 0, 0.3
set tmargin 3.5; set bmargin 0.5
set title "Relaxed 64-primary BCCA cluster hits an adhesive wall at 0.5 d/τ (JKR, γ/k_n = 0.01,\nvisco-elastic A = 0.5 τ, Mindlin μ = 0.3, rolling ξ_{crit} = 0.01 d, twisting)" font ",11"
set xrange [0:t_end]
set yrange [-0.05:1.02]
set format x ""
set ylabel "energy / E_{kin}(0)"
set key center right font ",11"
plot file skip 1 using 2:($3 / E0) with linespoints pt 7 ps 0.6 lw 2 lc rgb "black" title "kinetic (translation + rotation)", \
     file skip 1 using 2:($5 / E0) with linespoints pt 7 ps 0.6 lw 2 lc rgb grey title "contact elastic (0 at touching)", \
     file skip 1 using 2:($6 / E0) with linespoints pt 5 ps 0.6 lw 2 lc rgb blue title "dissipated: normal damping", \
     file skip 1 using 2:($7 / E0) with linespoints pt 9 ps 0.7 lw 2 lc rgb red title "dissipated: friction (Mindlin slip)", \
     file skip 1 using 2:($8 / E0) with linespoints pt 11 ps 0.7 lw 2 lc rgb green title "dissipated: rolling slip", \
     file skip 1 using 2:($9 / E0) with linespoints pt 13 ps 0.7 lw 2 lc rgb orange title "dissipated: twisting slip", \
     file skip 1 using 2:($10 / E0) with linespoints pt 3 ps 0.7 lw 2 lc rgb purple title "dissipated: contacts broken (JKR)", \
     file skip 1 using 2:(-$11 / E0) with lines dt 3 lw 2 lc rgb brown title "- work on stiffening springs"

unset title
set size 1, 0.3; set origin 0, 0
set tmargin 0.5; set bmargin 3.5
set format x "%g"
set xlabel sprintf("time  t / τ    (τ = (m/k_n)^{1/2}; automatic Δt = %.4f τ, one point per %d steps)", dt, every)
set ylabel "balance error × 10^3" offset 1,0
set yrange [*:*]  # stats honours the current range
stats file skip 1 using (1e3 * $12 / E0) nooutput
span = STATS_max - STATS_min
tic = span > 0 ? 10.0**floor(log10(span)) : 1
tic = span / tic < 2 ? tic / 2 : (span / tic < 5 ? tic : 2 * tic)
set yrange [STATS_min - 0.1 * span:STATS_max + 0.35 * span]
set ytics tic
set key top right font ",10"
plot file skip 1 using 2:(1e3 * $12 / E0) with linespoints pt 7 ps 0.6 lw 2 lc rgb red \
       title "[E_{kin} + E_{el} + dissipated - stiffening work](t) - (same at t = 0), over E_{kin}(0)"
unset multiplot
