# The JKR normal force versus overlap (report eqs 2 and 5, figure 1) with its loading/unloading
# hysteresis, as the law JkrNormal::respond computes it, and the Hertz force for comparison.
load here."/common.gnuplot"
file = data."/jkr_force.csv"
set output out."/jkr_force.png"
set title "JKR normal force between two unit spheres (γ/k_n = 0.01): hysteresis loop and Hertz"
set xlabel "overlap  δ / δ_c    (δ_c = a_0^2 / (2 6^{1/3} R^*), eq 3)"
set ylabel "normal force  F / F_c    (F_c = 3πγd/4, eq 5; > 0 repulsive)"
set xrange [-2:6]
set yrange [-1.8:6]
set xzeroaxis lt 1 lc rgb "#999999" lw 1
set yzeroaxis lt 1 lc rgb "#999999" lw 1
set key top left
# Landmarks of the loop (eqs 2 and 5 at a/a0 = (2/3)^(2/3), 1, 4^(-1/3), 6^(-2/3)).
x_touch = (2.0 / 3) ** (2.0 / 3); x_pull = 4 ** (-1.0 / 3); x_break = 6 ** (-2.0 / 3)
D(x) = 6 ** (1.0 / 3) * (2 * x**2 - 4.0 / 3 * sqrt(x))
F(x) = 4 * (x**3 - x**1.5)
set label 1 "touching: F = -8F_c/9" at D(x_touch) + 0.15, F(x_touch) - 0.12 font ",10"
set label 2 "equilibrium a = a_0" at D(1) + 0.2, F(1) - 0.25 font ",10"
set label 3 "pull-off: F = -F_c" at D(x_pull), F(x_pull) - 0.2 font ",10" center
set label 4 "break: F = -5F_c/9" at -1.1, F(x_break) - 0.15 font ",10" right
set arrow 1 from 0, 0 to 0, F(x_touch) lw 1.5 lc rgb blue head filled size 0.12,20
set arrow 2 from -1, F(x_break) to -1, 0 lw 1.5 lc rgb red head filled size 0.12,20
set arrow 3 from -1.9, 0.3 to -0.3, 0.3 lw 1.5 lc rgb blue head filled size 0.12,20
set label 5 "loading: F = 0 until the surfaces touch" at -1.9, 0.55 font ",10" tc rgb blue
set arrow 4 from -0.15, -0.3 to -0.9, -0.3 lw 1.5 lc rgb red head filled size 0.12,20
set label 6 "unloading: the contact holds in tension down to δ = -δ_c, then lets go" at -1.9, -1.6 font ",10" tc rgb red left
plot file skip 1 using 2:($1 == 1 ? $4 : NaN) with lines lw 2.5 lc rgb "black" \
       title "theory: eq 5 along eq 2 (stable branch)", \
     file skip 1 using 2:5 with lines lw 2 dt 2 lc rgb grey title "Hertz, no adhesion", \
     file skip 1 every 6 using 2:($1 == 0 ? $3 : NaN) with points pt 6 ps 1.1 lc rgb blue \
       title "law, loading (approach)", \
     file skip 1 every 6::3 using 2:($1 == 1 ? $3 : NaN) with points pt 7 ps 0.6 lc rgb red \
       title "law, unloading (retraction)", \
     "+" using (D(x_touch)):(F(x_touch)) every ::0::0 with points pt 9 ps 1.8 lc rgb "black" notitle, \
     "+" using (D(1)):(0) every ::0::0 with points pt 9 ps 1.8 lc rgb "black" notitle, \
     "+" using (D(x_pull)):(-1) every ::0::0 with points pt 9 ps 1.8 lc rgb "black" notitle, \
     "+" using (D(x_break)):(F(x_break)) every ::0::0 with points pt 9 ps 1.8 lc rgb "black" notitle
