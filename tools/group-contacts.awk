# Groups a run's real contacts ("wall@time;wall@time...", fsi-movie's contact_sequence)
# for reading: touch-downs on the same wall less than `gap` seconds (default 0.1) after the
# previous one become one item "wall@first..last (N touch-downs)". A ball rubbing over a
# tread's edge touches the corner, lets go for a step and touches again: the engine reports
# each, which is right, but a list of nine of them in 0.05 s says less than one interval.
#   awk -f tools/group-contacts.awk [-v gap=SECONDS] <<< "4@11.6472;4@11.6492;6@13.1"
#   -> 4@11.6472..11.6492 (2 touch-downs);6@13.1000
BEGIN { FS = ";"; if (gap == "") gap = 0.1 }
function flush() {
  if (n == 0) return
  item = n == 1 ? sprintf("%s@%.4f", wall, first) : sprintf("%s@%.4f..%.4f (%d touch-downs)", wall, first, last, n)
  out = out == "" ? item : out ";" item
  n = 0
}
{
  for (i = 1; i <= NF; ++i) {
    if ($i == "") continue
    split($i, a, "@")
    if (n > 0 && a[1] == wall && a[2] - last < gap) { last = a[2]; ++n; continue }
    flush()
    wall = a[1]; first = last = a[2]; n = 1
  }
}
END { flush(); print out }
