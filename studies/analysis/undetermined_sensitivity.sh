#!/usr/bin/env bash
# How much does v50 of break-up move with the cases left undetermined at the time limit?
#
#   studies/analysis/undetermined_sensitivity.sh STORE...
#
# The adaptive search and the correlations leave undetermined cases out of their fits (they never
# guess). Left out is unbiased only if a case's chance of ending undetermined does not depend on its
# class. Per store and wall this fits the logistic regression of break-up in ln v (R's glm, maximum
# likelihood) four ways: undetermined cases left out (the search's fit, without Firth's
# penalty); counted by their state at the time limit (mass off the wall and, on a wall without
# adhesion, no piece holding the bounce share 0.9: a break-up); all counted as break-ups; none
# counted as break-ups. The last two are bounds no physics suggests, the second a reading of states
# that may still change (docs/IMPACT.md section 5). Needs sqlite3 and R (Debian: r-base-core).
set -euo pipefail
[ $# -ge 1 ] || { sed -n 2,13p "$0"; exit 2; }
csv=$(mktemp)
trap 'rm -f "$csv"' EXIT
for store in "$@"; do
  sqlite3 -csv "$store" "SELECT c.primaries, json_extract(c.document, '\$.wall.adhesive'),
      json_extract(c.document, '\$.impact.speed'), r.outcome, r.largest_fragment_share,
      r.retained_mass_fraction FROM results r JOIN cases c ON c.id = r.case_id" > "$csv"
  Rscript --vanilla - "$csv" <<'R'
d <- read.csv(commandArgs(TRUE)[1], header = FALSE,
              col.names = c("N", "adhesive", "v", "outcome", "share", "retained"))
for (n in sort(unique(d$N))) for (wall in c(1, 0)) {
  s <- d[d$N == n & d$adhesive == wall, ]
  if (nrow(s) == 0) next
  undetermined <- s$outcome == "undetermined"
  broke <- s$outcome == "break-up"
  left_wall <- 1 - s$retained > 1e-9
  last_state <- if (wall == 1) left_wall else left_wall & s$share < 0.9
  ways <- list("left out" = list(!undetermined, broke),
               "by state at the limit" = list(TRUE, ifelse(undetermined, last_state, broke)),
               "all break-ups" = list(TRUE, broke | undetermined),
               "no break-up" = list(TRUE, broke & !undetermined))
  for (way in names(ways)) {
    keep <- rep(ways[[way]][[1]], length.out = nrow(s))
    y <- rep(ways[[way]][[2]], length.out = nrow(s))[keep]
    fit <- suppressWarnings(glm(y ~ log(s$v[keep]), family = binomial))
    cat(sprintf("N = %4d  %-17s undetermined %2d of %3d  %-22s v50 = %6.2f m/s\n", n,
                if (wall == 1) "adhesive wall" else "without adhesion", sum(undetermined), nrow(s), way,
                exp(-coef(fit)[1] / coef(fit)[2])))
  }
}
R
done
