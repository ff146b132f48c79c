# Sourced by the benchmark scripts: fields of a vesicle-iga log held in
# $log and of a run's time-series.csv.
#   log_unknowns            the unknown count of the first "N unknowns"
#   log_total               TimerOutput's total wall time (s)
#   log_section NAME        the wall time of one TimerOutput section (s)
#   log_peak_mb             the largest peak memory per rank (MB)
#   log_sum NAME...          the summed wall time of several sections (s)
#   series_counts DIR       "steps newton krylov" summed over DIR/time-series.csv
# and sets the threads per rank: THREADS (default 1). deal.II's WorkStream
# otherwise lets a rank that runs alone assemble on every core, and a
# "1 rank" figure is then one of 2 cores (the 3D electromechanics Jacobian:
# 26.9 s with one thread, 15.9 s with two; doc/performance.md).
export DEAL_II_NUM_THREADS=${THREADS:-1}
log_unknowns() { echo "$log" | sed -n 's/.* \([0-9]*\) unknowns.*/\1/p' | head -1; }
log_total() { echo "$log" | sed -n 's/^| Total wallclock time elapsed since start *| *\([0-9.e+-]*\)s.*/\1/p'; }
log_section() { echo "$log" | sed -n "s/^| $1 *| *[0-9]* | *\([0-9.e+-]*\)s.*/\1/p" | head -1; }
log_peak_mb() { echo "$log" | sed -n 's/^peak memory (VmHWM) per rank: max \([0-9.]*\) MB.*/\1/p'; }
series_counts() { awk -F, 'NR>1 {s++; n+=$4; k+=$5} END {print s, n, k}' "$1/time-series.csv"; }
log_sum() { local s=0 v; for n in "$@"; do v=$(log_section "$n"); s=$(awk -v a=$s -v b=${v:-0} 'BEGIN {print a + b}'); done; echo $s; }
