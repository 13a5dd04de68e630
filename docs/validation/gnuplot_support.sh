# Sourced by the figure scripts of docs/validation: installs gnuplot (Debian's gnuplot-nox) when it
# is missing, through apt-get (root or sudo), and picks the PNG terminal (pngcairo, else png).
ensure_gnuplot() {
  if ! command -v gnuplot >/dev/null; then
    local sudo=""
    [[ $(id -u) -ne 0 ]] && sudo=sudo
    $sudo apt-get install -y --no-install-recommends gnuplot-nox
  fi
  if gnuplot -e "set terminal" 2>&1 | grep -qw pngcairo; then png_terminal=pngcairo; else png_terminal=png; fi
}

# Radius of gyration of the primaries' centres of an "x y z r" file (lines starting with # skipped).
radius_of_gyration() {
  awk '!/^#/ && NF >= 3 { n++; x += $1; y += $2; z += $3; xx += $1*$1; yy += $2*$2; zz += $3*$3 }
       END { printf "%.2f", sqrt((xx + yy + zz) / n - (x*x + y*y + z*z) / (n*n)) }' "$1"
}

# Contacts: pairs of primaries whose centres are closer than the sum of their radii.
contact_count() {
  awk '!/^#/ && NF >= 4 { x[n] = $1; y[n] = $2; z[n] = $3; r[n] = $4; n++ }
       END { for (i = 0; i < n; i++) for (j = i + 1; j < n; j++) {
               d2 = (x[i]-x[j])^2 + (y[i]-y[j])^2 + (z[i]-z[j])^2
               if (d2 < (r[i] + r[j])^2) c++ }
             print c + 0 }' "$1"
}
