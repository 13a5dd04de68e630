# Coefficient of restitution of a unit sphere hitting an adhesive wall head-on (JKR, gamma/k_n = 0.01)
# at the automatic time step, against e = sqrt(1 - U_b / (m v^2 / 2)) = sqrt(1 - (v_c / v)^2), U_b
# the energy of one JKR cycle for each separation rule (v_c differs between them).
load here."/common.gnuplot"
file = data."/restitution.csv"
set output out."/restitution.png"
stats file skip 1 using ($1 == 0 ? $6 / $2 : NaN) nooutput
vc = STATS_mean
stats file skip 1 using ($1 == 1 ? $6 / $2 : NaN) nooutput
vc_force = STATS_mean

set multiplot
# Top panel: e(v).
set lmargin 11; set rmargin 3
set size 1, 0.68; set origin 0, 0.32
set bmargin 0.5; set tmargin 2.5
set title sprintf("Sphere on an adhesive wall (JKR, γ/k_n = 0.01, no friction), automatic step: v_c = %.4f, %.4f d/τ", vc, vc_force)
set logscale x
set xrange [0.45:22]
set yrange [-0.03:1.05]
set format x ""
set xtics add ("" 0.5, "" 2, "" 5, "" 20)
set ylabel "restitution  e = v_{out} / v_{in}"
set key top left font ",10" samplen 1.5
set samples 3000
e(x) = x < 1 ? 0 : sqrt(1 - 1 / x**2)
plot e(x) with lines lw 2 lc rgb "black" title "theory: e = (1 - U_b/(mv^2/2))^{1/2}", \
     file skip 1 using ($1 == 0 ? $2 : NaN):3 with points pt 7 ps 1.1 lc rgb blue title "DEM, displacement rule (δ = -δ_c)", \
     file skip 1 using ($1 == 1 ? $2 : NaN):3 with points pt 6 ps 1.1 lc rgb green title "DEM, force rule (F = -F_c)", \
     file skip 1 using ($1 == 0 ? $2 : NaN):5 with points pt 5 ps 0.9 lc rgb red title "displacement rule + damping, A = 0.05 τ"

# Bottom panel: e_sim / e_theory - 1 against the 1 % the automatic step must meet.
unset title
set size 1, 0.32; set origin 0, 0
set tmargin 0.5; set bmargin 3.5
set format x "%g"
set xtics add ("0.5" 0.5, "2" 2, "5" 5, "20" 20)
set xlabel "impact speed  v / v_c"
set ylabel "(e_{sim} / e_{theory} - 1) × 10^2" offset 1,0
set yrange [-2.2:1.4]
set ytics 1
set key bottom center horizontal samplen 1.5 font ",10"
plot 1 with lines dt 2 lw 1.5 lc rgb grey title "± 1 % (docs/MODEL.md 9.2)", \
     -1 with lines dt 2 lw 1.5 lc rgb grey notitle, \
     file skip 1 using ($1 == 0 && $4 > 0 ? $2 : NaN):(1e2 * ($3 / $4 - 1)) with points pt 7 ps 0.9 lc rgb blue title "displacement rule", \
     file skip 1 using ($1 == 1 && $4 > 0 ? $2 : NaN):(1e2 * ($3 / $4 - 1)) with points pt 6 ps 0.9 lc rgb green title "force rule"
unset multiplot
