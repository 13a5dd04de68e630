# Coefficient of restitution of a unit sphere hitting an adhesive wall head-on (JKR, gamma/k_n = 0.01)
# against e = sqrt(1 - U_b / (m v^2 / 2)) = sqrt(1 - (v_c / v)^2), U_b the JKR hysteresis loss.
load here."/common.gnuplot"
file = data."/restitution.csv"
set output out."/restitution.png"
stats file skip 1 using ($6 / $1) nooutput
vc = STATS_mean

set multiplot
# Top panel: e(v).
set lmargin 11; set rmargin 3
set size 1, 0.68; set origin 0, 0.32
set bmargin 0.5; set tmargin 2.5
set title sprintf("Sphere on an adhesive wall (JKR, γ/k_n = 0.01, no friction): v_c = %.4f d/τ", vc)
set logscale x
set xrange [0.45:22]
set yrange [-0.03:1.05]
set format x ""
set xtics add ("" 0.5, "" 2, "" 5, "" 20)
set ylabel "restitution  e = v_{out} / v_{in}"
set key bottom right
set samples 3000
e(x) = x < 1 ? 0 : sqrt(1 - 1 / x**2)
plot e(x) with lines lw 2 lc rgb "black" title "theory, no damping: e = (1 - U_b/(mv^2/2))^{1/2}", \
     file skip 1 using 1:2 with points pt 7 ps 1.1 lc rgb blue title "DEM: JKR, no damping", \
     file skip 1 using 1:4 with points pt 5 ps 0.9 lc rgb red title "DEM: JKR + visco-elastic damping, A = 0.05 τ"

# Bottom panel: e_sim - e_theory against the step-discretisation bound of jkr_impact_test.cpp.
unset title
set size 1, 0.32; set origin 0, 0
set tmargin 0.5; set bmargin 3.5
set format x "%g"
set xtics add ("0.5" 0.5, "2" 2, "5" 5, "20" 20)
set xlabel "impact speed  v / v_c"
set ylabel "(e_{sim} - e_{theory}) × 10^3" offset 1,0
set yrange [-3.5:3.5]
set ytics 1
set key bottom right horizontal samplen 1.5 font ",10"
plot file skip 1 using 1:($3 > 0 ? 1e3 * $5 : NaN) with lines dt 2 lw 1.5 lc rgb grey \
       title "± bound 2F_c vΔt / (m v^2 e)", \
     file skip 1 using 1:($3 > 0 ? -1e3 * $5 : NaN) with lines dt 2 lw 1.5 lc rgb grey notitle, \
     file skip 1 using 1:($3 > 0 ? 1e3 * ($2 - $3) : NaN) with points pt 7 ps 0.9 lc rgb blue title "no damping"
unset multiplot
