# The fits of undetermined_sensitivity.sh (read that script's header): per N and wall, the logistic
# regression of break-up in ln v, each way of counting the undetermined cases, by maximum likelihood
# (R's glm) and by Firth's penalised likelihood (Firth, Biometrika 80 (1993) 27; the adaptive
# search's fit, docs/ADAPTIVE.md "The method"), each with its 95 % profile interval of v50.
#   Rscript --vanilla undetermined_sensitivity.R CASES.csv [RERUNS.csv]
# CASES.csv: id, N, adhesive (1/0), v (m/s), outcome, largest fragment share, retained mass fraction.
# RERUNS.csv: id, outcome, largest fragment share, retained mass fraction, simulated time (s).

# Log-likelihood of logit P = b0 + b1 x, plus Firth's penalty 0.5 ln det I(b) when penalised.
log_likelihood <- function(b, x, y, penalised) {
  eta <- b[1] + b[2] * x
  l <- sum(ifelse(y, plogis(eta, log.p = TRUE), plogis(-eta, log.p = TRUE)))
  if (!penalised) return(l)
  w <- plogis(eta) * plogis(-eta)
  information <- matrix(c(sum(w), sum(w * x), sum(w * x), sum(w * x^2)), 2)
  l + 0.5 * log(max(det(information), .Machine$double.xmin))  # det 0 where every w underflows
}

# Every break-up beyond every other outcome (or the other way round): no maximum-likelihood estimate.
separated <- function(x, y) {
  if (all(y) || !any(y)) return(TRUE)
  max(x[y]) < min(x[!y]) || max(x[!y]) < min(x[y])
}

# The maximum of each likelihood: coefficients (par) and the negated log-likelihood there (value).
# Firth's by Nelder-Mead, then polished by BFGS, both to a relative 1e-15: BFGS alone from the
# glm's estimate stopped short on small separated samples.
maximum_likelihood_fit <- function(x, y) {
  fit <- glm(y ~ x, family = binomial)
  list(par = unname(coef(fit)), value = -as.numeric(logLik(fit)))
}
firth_fit <- function(x, y) {
  objective <- function(b) -log_likelihood(b, x, y, TRUE)
  control <- list(reltol = 1e-15, maxit = 10000)
  best <- optim(c(0, 1), objective, method = "Nelder-Mead", control = control)
  optim(best$par, objective, method = "BFGS", control = control)
}

# v50 = exp(theta), theta = -b0 / b1, and its 95 % profile interval: the thetas whose profile
# (log-)likelihood, maximised over b1 with b0 = -b1 theta, is within qchisq(0.95, 1) / 2 of the
# maximum, searched over the speeds' span widened by the span on each side (NA: open there).
# The doses are centred on the middle of their span (as the search centres them on its range's).
v50_fit <- function(x, y, penalised) {
  if (!penalised && separated(x, y)) return(c(NA, NA, NA))
  centre <- mean(range(x))
  x <- x - centre
  best <- if (penalised) firth_fit(x, y) else maximum_likelihood_fit(x, y)
  theta <- -best$par[1] / best$par[2]
  slope_bound <- 20 * abs(best$par[2]) + 10
  profile <- function(t) {
    optimize(function(b1) log_likelihood(c(-b1 * t, b1), x, y, penalised), c(-1, 1) * slope_bound,
             maximum = TRUE)$objective
  }
  drop <- function(t) 2 * (-best$value - profile(t)) - qchisq(0.95, 1)
  span <- diff(range(x))
  end <- function(bound) {
    if (!is.finite(theta) || drop(bound) < 0) return(NA)
    uniroot(drop, sort(c(theta, bound)), tol = 1e-8)$root
  }
  exp(centre + c(theta, end(min(x) - span), end(max(x) + span)))
}

format_fit <- function(f) {
  if (is.na(f[1])) return(sprintf("%-21s", "  none (separated)"))
  ends <- ifelse(is.na(f[2:3]), "open", sprintf("%.2f", f[2:3]))
  sprintf("%6.2f [%s, %s]", f[1], ends[1], ends[2])
}

# A case's class by its state at the time limit: mass off the wall and, on a wall without
# adhesion, no piece holding the bounce share 0.9: a break-up.
break_up_by_state <- function(s, wall) {
  left_wall <- 1 - s$retained > 1e-9
  if (wall == 1) left_wall else left_wall & s$share < 0.9
}

# The ways of counting: which cases enter the fit, and which of them are break-ups.
ways_of_counting <- function(s, wall) {
  undetermined <- s$outcome == "undetermined"
  broke <- s$outcome == "break-up"
  ways <- list("left out" = list(!undetermined, broke),
               "by state at the limit" = list(TRUE, ifelse(undetermined, break_up_by_state(s, wall), broke)),
               "all break-ups" = list(TRUE, broke | undetermined),
               "no break-up" = list(TRUE, broke & !undetermined))
  if (is.null(s$rerun_outcome)) return(ways)
  rerun <- !is.na(s$rerun_outcome)
  r <- data.frame(outcome = ifelse(rerun, s$rerun_outcome, s$outcome), share = ifelse(rerun, s$rerun_share, s$share),
                  retained = ifelse(rerun, s$rerun_retained, s$retained))
  still <- r$outcome == "undetermined"
  c(ways, list("rerun, rest left out" = list(!still, r$outcome == "break-up"),
               "rerun, rest by state" = list(TRUE, ifelse(still, break_up_by_state(r, wall), r$outcome == "break-up"))))
}

report_group <- function(s, n, wall) {
  ways <- ways_of_counting(s, wall)
  label <- if (wall == 1) "adhesive wall" else "without adhesion"
  if (!is.null(s$rerun_outcome)) {
    rerun <- !is.na(s$rerun_outcome)
    counts <- table(s$rerun_outcome[rerun])
    cat(sprintf("N = %4d  %-17s reruns %2d%s\n", n, label, sum(rerun),
                if (sum(rerun) > 0) paste0(": ", paste(names(counts), counts, collapse = ", ")) else ""))
  }
  for (way in names(ways)) {
    keep <- rep(ways[[way]][[1]], length.out = nrow(s))
    y <- rep(ways[[way]][[2]], length.out = nrow(s))[keep]
    x <- log(s$v[keep])
    cat(sprintf("N = %4d  %-17s undetermined %2d of %3d  %-22s v50 = %s m/s  Firth %s\n", n, label,
                sum(s$outcome == "undetermined"), nrow(s), way, format_fit(v50_fit(x, y, FALSE)),
                format_fit(v50_fit(x, y, TRUE))))
  }
}

args <- commandArgs(TRUE)
d <- read.csv(args[1], header = FALSE, col.names = c("id", "N", "adhesive", "v", "outcome", "share", "retained"))
if (length(args) > 1) {
  r <- read.csv(args[2], header = FALSE, col.names = c("id", "outcome", "share", "retained", "time"))
  m <- match(d$id, r$id)
  d$rerun_outcome <- r$outcome[m]
  d$rerun_share <- r$share[m]
  d$rerun_retained <- r$retained[m]
}
for (n in sort(unique(d$N))) for (wall in c(1, 0)) {
  s <- d[d$N == n & d$adhesive == wall, ]
  if (nrow(s) > 0) report_group(s, n, wall)
}
