# Energy error of a bonded JKR dimer oscillating in its well versus the time step: velocity Verlet
# is second order, so the error falls as dt^2 (slope 2 on log-log axes).
load here."/common.gnuplot"
file = data."/conservation.csv"
set output out."/dt_convergence.png"
# Anchor the slope-2 guide on the coarsest point, a factor 3 above the data.
stats file skip 1 using 2 nooutput
dt_max = STATS_max
stats file skip 1 using ($2 == dt_max ? $3 : NaN) nooutput
err_max = STATS_max
set title "Bonded JKR dimer (γ/k_n = 0.01, no friction) oscillating for 200 τ: energy error vs time step"
set logscale xy
set xlabel "time step  Δt / τ    (τ = (m/k_n)^{1/2})"
set ylabel "max_t |E(t) - E_0| / reference energy"
set format y "10^{%L}"
set xrange [0.01:0.3]
set yrange [1e-5:0.2]
set key bottom right
set x2tics () out nomirror
set xtics nomirror
set x2label "steps per contact period  (SimulationSettings::steps\\_per\\_period)"
set tmargin 5
set x2range [0.01:0.3]
set logscale x2
set for [k=0:4] x2tics add (sprintf("%d", 25 * 2**k) dt_max / 2**k)
plot 3 * err_max * (x / dt_max)**2 with lines dt 2 lw 2 lc rgb grey title "slope 2: ∝ Δt^2", \
     file skip 1 using 2:3 with linespoints pt 7 ps 1.4 lw 1 lc rgb blue title "reference |E_0| (E = 0 at touching)", \
     file skip 1 using 2:4 with linespoints pt 5 ps 1.3 lw 1 lc rgb red title "reference E_0 - E_{min} (oscillation energy)"
