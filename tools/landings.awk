# The landings of a ball in one run's functionals.csv (fsi-movie output): each time it
# comes within the contact force's reach of a wall, which wall, when and how close.
#
#   awk -f tools/landings.awk -v walls="AX,AY,BX,BY;..." -v dist0=1e-2 functionals.csv
#
# prints one CSV line per landing:
#   wall,time_s,distance_m,enter_s,leave_s,walls,rise_m
# wall: the index into `walls` (the scenario's order) at the closest approach; time_s,
# distance_m: the closest approach; enter_s, leave_s: when the ball came within dist0 and
# when it left again (empty: still there in the last row, i.e. resting or rolling at the
# end); walls: the walls it was over during the landing, in order, joined by '>' (e.g.
# "1>2": landed at the foot of the plane and rolled onto tread 1); rise_m: the rebound, how
# far the centroid rose above where it was at the closest approach before the next landing
# began (or the file ended: a run stopped mid-flight gives a lower bound); empty for a
# landing that lasts to the end.
#
# This is the chapter's notion of a "contact" on the stairs (Sect. 12.6.5: "the next contact
# is on the right part of the first stair"): with the penalty force the ball does not touch,
# it comes within dist_0 (where P_c acts) and bounces. The engine's real contacts (the
# interface on a wall) are in summary.json; they are landings here as well.
#
# A landing starts when min_distance_m drops below dist0 and ends when it rises above
# leave_factor * dist0 (default 2: a hop of less than 2 cm at dist0 = 1e-2 m is rolling,
# not a new bounce; the hysteresis keeps a ball skimming along at ~dist0 from counting a
# landing per wiggle). The wall is the one nearest to the ball's centroid (the ball is
# round to within millimetres; the wall nearest its centre is the wall under it); rolling
# from one wall onto the next within the reach stays one landing. Rows with a relative
# mass error above max_mass_error (default 0.5, a degenerated body) are skipped.
BEGIN {
  FS = ","
  if (max_mass_error == "") max_mass_error = 0.5
  if (leave_factor == "") leave_factor = 2
  if (dist0 + 0 <= 0) { print "landings.awk: needs -v dist0=... > 0" > "/dev/stderr"; exit 2 }
  n_walls = split(walls, w, ";")
  if (n_walls == 0) { print "landings.awk: needs -v walls=\"AX,AY,BX,BY;...\"" > "/dev/stderr"; exit 2 }
  for (i = 1; i <= n_walls; ++i) {
    if (split(w[i], c, ",") != 4) { print "landings.awk: wall " i - 1 " is not AX,AY,BX,BY: " w[i] > "/dev/stderr"; exit 2 }
    ax[i - 1] = c[1]; ay[i - 1] = c[2]; bx[i - 1] = c[3]; by[i - 1] = c[4]
  }
  inside = 0
}
NR == 1 {
  for (i = 1; i <= NF; ++i) col[$i] = i
  for (k in need) delete need[k]
  split("time_s min_distance_m centroid_x_m centroid_y_m", need, " ")
  for (k in need) if (!(need[k] in col)) {
    print "landings.awk: " FILENAME " lacks the " need[k] " column" > "/dev/stderr"; exit 2
  }
  next
}
("mass_error" in col) && $col["mass_error"] + 0 > max_mass_error { next }
{
  t = $col["time_s"] + 0; d = $col["min_distance_m"] + 0
  wall = nearest_wall($col["centroid_x_m"] + 0, $col["centroid_y_m"] + 0)
  y = $col["centroid_y_m"] + 0
  if (inside && d > leave_factor * dist0) {
    left = sprintf("%.4f", t)
    inside = 0
  }
  if (!inside && d < dist0) {
    if (left != "") emit()
    inside = 1; enter = t; closest = d + 1; visited = ""; last_wall = -1; left = ""
  }
  if (y > apex_y) apex_y = y
  if (!inside) next
  if (d < closest) { closest = d; closest_t = t; landing_wall = wall; closest_y = y; apex_y = y }
  if (wall != last_wall) { visited = visited (visited == "" ? "" : ">") wall; last_wall = wall }
}
END { if (inside || left != "") emit() }

# One landing; `left` is empty while the ball is still within reach.
function emit() {
  printf "%d,%.4f,%.4e,%.4f,%s,%s,%s\n", landing_wall, closest_t, closest, enter, left, visited,
         (left == "" ? "" : sprintf("%.4e", apex_y - closest_y))
}

# Index of the wall segment nearest to (x, y).
function nearest_wall(x, y,   i, best, best_d, dx, dy, l2, s, px, py, dd) {
  best = -1; best_d = 1e300
  for (i = 0; i < n_walls; ++i) {
    dx = bx[i] - ax[i]; dy = by[i] - ay[i]; l2 = dx * dx + dy * dy
    s = l2 > 0 ? ((x - ax[i]) * dx + (y - ay[i]) * dy) / l2 : 0
    if (s < 0) s = 0; else if (s > 1) s = 1
    px = ax[i] + s * dx - x; py = ay[i] + s * dy - y; dd = px * px + py * py
    if (dd < best_d) { best_d = dd; best = i }
  }
  return best
}
