# Radius of gyration of ballistic cluster-cluster aggregates versus the number of primaries (report
# figure 2b) and the fitted fractal scaling N = k_f (Rg / a)^D_f, a = d/2.
load here."/common.gnuplot"
set output out."/rg_vs_n.png"
fit_file = data."/rg_fit.csv"
stats fit_file skip 1 using 1 nooutput
Df = STATS_max
stats fit_file skip 1 using 2 nooutput
kf = STATS_max
stats fit_file skip 1 using 3 nooutput
se = STATS_max
set title "Hierarchical BCCA (Jullien 1984), monodisperse d = 1: 16 clusters per size"
set logscale xy
set xlabel "number of primaries  N"
set ylabel "radius of gyration  R_g / d"
set xrange [10:6000]
set yrange [1:80]
set format x "%g"
set format y "%g"
set ytics (1, 2, 5, 10, 20, 50)
set xtics (16, 32, 64, 128, 256, 512, 1024, 2048, 4096)
set key top left
Rg(n) = 0.5 * (n / kf) ** (1.0 / Df)
plot data."/rg_samples.csv" skip 1 using 1:2 with points pt 6 ps 0.6 lc rgb "#aaaaaa" title "single clusters", \
     data."/rg_vs_n.csv" skip 1 using 1:2:3 with yerrorbars pt 7 ps 1.3 lw 1.5 lc rgb blue \
       title "mean R_g ± standard deviation", \
     Rg(x) with lines lw 2 lc rgb red \
       title sprintf("fit N = k_f (R_g/a)^{D_f}: D_f = %.3f ± %.3f, k_f = %.2f", Df, se, kf), \
     NaN with lines lw 0 lc rgb "white" title "report (figure 2b): D_f ≈ 2.05;  Jullien 1984: D_f ≈ 1.9-2.0"
