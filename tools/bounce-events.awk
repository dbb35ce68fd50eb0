# Reduces one run's functionals CSV (fsi-movie's functionals.csv or fsi-bench-run --csv)
# of a ball dropped onto the ground to the events that a time step can move:
#   turn_time_s,turn_distance_m,first_min_distance_m,rebound_max_m,rebound_max_time_s,second_contact_time_s
#   awk -f tools/bounce-events.awk functionals.csv
#
# turn: the first time the body's mean vertical velocity changes from down to up, and the
#   distance to the ground then (both interpolated linearly between the rows, so that runs
#   with other step lengths compare at the same instant).
# first_min_distance: the smallest distance of the first contact (until the ball has risen
#   2 mm above it: tools/example1-table.awk's rule).
# rebound_max: the largest distance after the first contact, with its time, refined by the
#   parabola through the largest row and its two neighbours (a long step near the apex
#   would otherwise round it down); it counts once the ball has fallen 2 mm below it.
# second_contact: the time the distance falls below second_contact_m (default 2e-3 m)
#   after the rebound maximum, interpolated.
# A field stays empty when the run did not get that far.
BEGIN {
  FS = ","; state = "fall"; dmin = 1e300; dmax = -1
  if (second_contact_m == "") second_contact_m = 2e-3
}
NR == 1 {
  for (i = 1; i <= NF; ++i) col[$i] = i
  if (!("time_s" in col) || !("min_distance_m" in col) || !("mean_vy_mps" in col)) {
    print "bounce-events: " FILENAME " lacks time_s/min_distance_m/mean_vy_mps columns" > "/dev/stderr"
    exit 2
  }
  next
}
{
  t = $col["time_s"] + 0; d = $col["min_distance_m"] + 0; v = $col["mean_vy_mps"] + 0
  if (state == "fall" || state == "contact") {
    if (turn_t == "" && have_prev && pv < 0 && v >= 0) {
      s = pv / (pv - v)
      turn_t = pt + s * (t - pt); turn_d = pd + s * (d - pd)
    }
    if (d < dmin) dmin = d
    if (dmin < 0.05 && d > dmin + 2e-3) state = "rebound"
  }
  if (state == "rebound") {
    if (d > dmax) { dmax = d; imax = NR; tm1 = pt; dm1 = pd; t0 = t; d0 = d; apex_next = 1 }
    else if (apex_next) { tp1 = t; dp1 = d; apex_next = 0 }
    if (d < dmax - 2e-3) {
      state = "second"
      rebound_d = dmax; rebound_t = t0
      # Parabola through (tm1, dm1), (t0, d0), (tp1, dp1): its vertex.
      a1 = (dm1 - d0) / (tm1 - t0); a2 = (dp1 - d0) / (tp1 - t0)
      c = (a2 - a1) / (tp1 - tm1)
      if (c < 0) {
        b = a1 - c * (tm1 - t0)  # slope at t0: d = d0 + b (t - t0) + c (t - t0)^2
        dt = -b / (2 * c)
        if (dt > tm1 - t0 && dt < tp1 - t0) { rebound_t = t0 + dt; rebound_d = d0 - b * b / (4 * c) }
      }
    }
  }
  if (state == "second" && have_prev && pd >= second_contact_m && d < second_contact_m) {
    second_t = pt + (pd - second_contact_m) / (pd - d) * (t - pt)
    state = "done"
  }
  pt = t; pd = d; pv = v; have_prev = 1
}
END {
  fmt = "%.6g"
  printf "%s,%s,%s,%s,%s,%s\n",
    turn_t == "" ? "" : sprintf(fmt, turn_t), turn_d == "" ? "" : sprintf(fmt, turn_d),
    dmin == 1e300 ? "" : sprintf(fmt, dmin), rebound_d == "" ? "" : sprintf(fmt, rebound_d),
    rebound_t == "" ? "" : sprintf(fmt, rebound_t), second_t == "" ? "" : sprintf(fmt, second_t)
}
