# Reduces one run's functionals.csv (fsi-movie output) of a ball bouncing on the ground to
#   first_rebound_max,second_rebound_max,rest_distance
#   awk -f tools/study-bounce.awk functionals.csv
#
# A contact ends with a local minimum of min_distance_m below 5 cm, confirmed once the
# ball has risen 0.5 mm above it; the rebound maximum is the largest distance after that,
# until the ball has come back down half way towards that minimum (tools/example1-table.awk's
# rule) while its mean vertical velocity points down: during a lift-off the distance,
# taken under the rim, wiggles by fractions of a millimetre while the ball rises
# (6.7e-4 -> 1.2e-3 -> 5.0e-4 m in Example 1), which is not a rebound; nor is a rise of
# the distance while the ball's mean vertical velocity never turned upward (a dimple's rim
# moving while the ball still approaches). rest_distance is the distance in the last row
# if the ball is at rest there: |mean_vy_mps| <= rest_speed (1e-4 m/s) in every row of the
# last rest_window_s (0.25 s, counted from the last row at or before t_end - 0.25 s, so
# that the rows span the whole window); a ball still settling or sinking (the contact study's
# balls sank at 2e-4 to 5e-3 m/s) has none. A value is empty when the run did not get
# that far (e.g. the ball stuck in real contact). A rebound still rising in the last row counts (the run
# ended in flight) unless -v stopped_early=1: a run stopped because its body degenerated
# ends in the wiggles of its failure, not in a rebound. Rows with
# a relative mass error above max_mass_error (default 0.5: the step at which fsi-movie
# stops a degenerated body) are not a ball any more and are skipped.
BEGIN {
  if (max_mass_error == "") max_mass_error = 0.5  # -v max_mass_error=... (study-common.sh)
  if (rest_speed == "") rest_speed = 1e-4          # m/s
  if (rest_window_s == "") rest_window_s = 0.25
  FS = ","; n = 0; state = "approach"; dmin = 1e300; dmax = -1 }
NR == 1 {
  for (i = 1; i <= NF; ++i) col[$i] = i
  if (!("min_distance_m" in col)) {
    print "study-bounce: " FILENAME " lacks the min_distance_m column" > "/dev/stderr"; exit 2
  }
  next
}
("mass_error" in col) && $col["mass_error"] + 0 > max_mass_error { next }
{
  d = $col["min_distance_m"] + 0; last = $col["min_distance_m"]
  # Without a velocity column every rise counts as the ball moving up.
  vy_known = "mean_vy_mps" in col
  if (vy_known && ("time_s" in col)) { ++rows; row_t[rows] = $col["time_s"] + 0; row_v[rows] = $col["mean_vy_mps"] + 0 }
  up = !vy_known || $col["mean_vy_mps"] + 0 > 0
  falling = !vy_known || $col["mean_vy_mps"] + 0 < 0
  if (state == "approach") {
    if (d < dmin) dmin = d
    if (dmin < 0.05 && d > dmin + 5e-4) { state = "rebound"; dmax = d; rose = up }
  } else if (state == "rebound") {
    if (d > dmax) dmax = d
    if (up) rose = 1
    if (falling && d < dmin + 0.5 * (dmax - dmin)) {
      if (!rose) {
        # The ball never moved up: the distance under a deforming rim wiggled while it
        # still approached (1e5 Pa: 2.6 -> 3.2 -> 0 mm at -0.11 m/s). Same contact.
        state = "approach"; if (d < dmin) dmin = d; dmax = -1
      } else {
        rebound[++n] = dmax
        if (n == 2) state = "done"; else { state = "approach"; dmin = d; dmax = -1 }
      }
    }
  }
}
END {
  # Still rising at the end: a rebound cut short by the end time, or, in a run that stopped
  # early, the last wiggle before the failure (not a rebound).
  if (state == "rebound" && rose && dmax > dmin + 5e-4 && !stopped_early) rebound[++n] = dmax
  # At rest: the rows from the last one at or before t_end - window on are all slower than
  # rest_speed (and they do span the window). Without time or velocity columns: the last row.
  rest = last == "" ? "" : sprintf("%.6e", last)
  if (rows > 0) {
    at_rest = 0
    for (i = rows; i >= 1; --i) {
      v = row_v[i] < 0 ? -row_v[i] : row_v[i]
      if (v > rest_speed) break
      if (row_t[i] <= row_t[rows] - rest_window_s) { at_rest = 1; break }
    }
    if (!at_rest) rest = ""
  }
  printf "%s,%s,%s\n", (1 in rebound ? sprintf("%.6e", rebound[1]) : ""),
         (2 in rebound ? sprintf("%.6e", rebound[2]) : ""), rest
}
