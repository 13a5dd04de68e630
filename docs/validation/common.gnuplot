# Shared settings of the validation figures; loaded by each *.gp script. The driver passes
# data (directory of validation_data's CSV files), out (figure directory) and term (pngcairo or png).
set encoding utf8
if (!exists("term")) term = "pngcairo"
if (term eq "pngcairo") {
  set terminal pngcairo size 900,600 enhanced font "DejaVu Sans,12" linewidth 1.5
} else {
  set terminal png size 900,600 enhanced font "DejaVuSans,11"
}
set datafile separator ","
set grid lc rgb "#dddddd" lw 1
set border lw 1.2
set key box opaque samplen 2.5 spacing 1.2
blue = "#1f77b4"; red = "#d62728"; green = "#2ca02c"; orange = "#ff7f0e"; purple = "#9467bd"
brown = "#8c564b"; grey = "#7f7f7f"; pink = "#e377c2"
