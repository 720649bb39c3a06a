# Shell helpers the benchmark scripts source: GNU time's wall time and peak
# memory of one command, and medians.

# median of the numbers on stdin
median() { sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }

# time_once OUT COMMAND...: runs it once, appends "SECONDS KILOBYTES" to OUT
time_once() {
  local out=$1; shift
  /usr/bin/time -f "%e %M" -o "$out.last" "$@" >/dev/null 2>&1 || true
  # the last line: GNU time puts "Command exited with non-zero status" before it
  tail -n 1 "$out.last" >> "$out"
}

# column N of FILE's lines, as a median
median_of() { awk -v c="$2" '{print $c}' "$1" | median; }
