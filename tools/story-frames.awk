# The steps of six moments of a bounce in one run's functionals.csv (fsi-movie output),
# for a contact sheet that tells the story: the start, the middle of the fall, the first
# closest approach (the squeeze film), the top of the rebound, the second closest
# approach, and the end.
#
#   awk -F, -f tools/story-frames.awk functionals.csv
#
# prints the six step numbers, one per line. A phase is over when the distance has moved
# 1 cm away from its extreme (the rebound rises 5-7 cm in Example 1); a run that never
# rebounds gives its closest approach for the later moments too.
NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
{
  step = $col["step"]; t = $col["time_s"]; d = $col["min_distance_m"]
  if (phase == 0) {                      # falling: follow the closest approach
    if (n == 0 || d < dmin) { dmin = d; film = step; film_t = t }
    if (d > dmin + 0.01) { phase = 1; dmax = d; top = step }
  } else if (phase == 1) {               # rebounding: follow the top
    if (d > dmax) { dmax = d; top = step }
    if (d < dmax - 0.01) { phase = 2; dmin2 = d; second = step }
  } else if (d < dmin2) { dmin2 = d; second = step }  # falling again
  ++n; steps[n] = step; times[n] = t; last = step
}
END {
  if (top == "") top = film
  if (second == "") second = top
  half = film_t / 2; fall = 0
  for (i = 1; i <= n; ++i) if (times[i] <= half) fall = steps[i]
  print 0; print fall; print film; print top; print second; print last
}
