# Reduces one run's functionals.csv (fsi-movie output) to the three Table 12.1 values.
#   awk -f tools/example1-table.awk -v nodes=4225 -v k=2e-3 functionals.csv
# Prints: nodes,k,min_distance_first_contact,max_distance_first_rebound,mass_error_t3
#
# First contact: the approach ends with the first local minimum of the distance below
# 5 cm, confirmed once the ball has risen 2 mm above it (or the run ends). First
# rebound: the largest distance after that, until the ball has come back down half way
# between that maximum and the first minimum; it counts once the ball has fallen 2 mm
# below it (a run that ends while the ball still rises leaves the field empty, with a
# remark). Mass error: the row nearest t = 3 s.
# Real contact (the discrete distance reaches 0; not expected in Example 1) ends the
# reduction: what comes after it is not trusted, the fields after it stay empty.
BEGIN { FS = ","; state = "approach"; dmin = 1e300; dmax = -1; best_dt = 1e300; mass = "" }
NR == 1 {
  for (i = 1; i <= NF; ++i) col[$i] = i
  if (!("time_s" in col) || !("min_distance_m" in col) || !("mass_error" in col)) {
    print "example1-table: " FILENAME " lacks time_s/min_distance_m/mass_error columns" > "/dev/stderr"
    exit 2
  }
  next
}
touched { next }
{
  t = $col["time_s"] + 0; d = $col["min_distance_m"] + 0
  if (d < 1e-12) { touched = 1; t_touch = t; if (state == "approach") { dmin = 0; tmin = t } ; next }
  if (state == "approach") {
    if (d < dmin) { dmin = d; tmin = t }
    if (dmin < 0.05 && d > dmin + 2e-3) state = "rebound"
  } else if (state == "rebound") {
    if (d > dmax) { dmax = d; tmax = t }
    if (d < dmax - 2e-3) confirmed = 1
    if (dmax > dmin && d < dmin + 0.5 * (dmax - dmin)) state = "done"
  }
  if ((t - 3.0) ^ 2 < best_dt) { best_dt = (t - 3.0) ^ 2; mass = $col["mass_error"] }
}
END {
  if (best_dt > 1e-4) mass = ""   # the run did not reach t = 3 s (or touched before)
  if (touched && state != "done") dmax = -1
  if (!touched && state == "approach") {
    printf "# first contact not reached (or not left by 2 mm) by the end of the run at t = %.4f s\n", t > "/dev/stderr"
    dmin = 1e300
  }
  unconfirmed = (!touched && state == "rebound" && !confirmed)
  if (unconfirmed) {
    printf "# rebound maximum not confirmed: %.4e m at t = %.4f s and the run ended before the ball fell 2 mm below it\n", dmax, tmax > "/dev/stderr"
    dmax = -1
  }
  if (touched) printf "# real contact at t = %.4f s: the rest of the run is not used\n", t_touch > "/dev/stderr"
  printf "%s,%s,%s,%s,%s\n", nodes, k, (dmin < 1e300 ? sprintf("%.6e", dmin) : ""),
         (dmax >= 0 ? sprintf("%.6e", dmax) : ""), mass
  if (dmin < 1e300) {
    printf "# first contact at t = %.4f s", tmin > "/dev/stderr"
    if (dmax >= 0) printf ", first rebound maximum at t = %.4f s", tmax > "/dev/stderr"
    printf "\n" > "/dev/stderr"
  }
}
