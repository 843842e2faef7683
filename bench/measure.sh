# Sourced by the bench scripts: `measure CMD ...` runs CMD $runs times
# (output discarded) and prints the median wall s, CPU s (user + system)
# and peak resident KB, as /usr/bin/time reports them. Needs $work (a
# scratch folder) and $runs.
measure() {
  i=0
  : > "$work/times"
  while [ "$i" -lt "$runs" ]; do
    /usr/bin/time -f "%e %U %S %M" -o "$work/one" "$@" > /dev/null 2>&1 || { echo "failed: $*" >&2; exit 1; }
    cat "$work/one" >> "$work/times"
    i=$((i + 1))
  done
  median() { sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
  wall=$(awk '{ print $1 }' "$work/times" | median)
  cpu=$(awk '{ print $2 + $3 }' "$work/times" | median)
  peak=$(awk '{ print $4 }' "$work/times" | median)
  echo "$wall $cpu $peak"
}
