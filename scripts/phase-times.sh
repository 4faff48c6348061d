# Sourced by the CI scripts (scripts/test.sh, test-sanitized.sh, fuzz.sh, .ci/run): the wall and CPU time of
# each phase of a run, so that CI's log ends with where its time went (docs/testing.md, "Robustness").
#
#   phase NAME COMMAND...   runs COMMAND and returns its status; when SHADOWFX_PHASE_TIMES names a file,
#                           appends "NAME<TAB>wall s<TAB>CPU s<TAB>status" to it. CPU is user + system time
#                           of COMMAND and of every process it waited for (bash's `times`), steadier than
#                           wall time on a loaded machine.
#   phase_start / phase_end NAME STATUS   the same around commands that are not one command (a loop).
#   print_phase_times FILE  the lines of FILE summed per NAME, in order of first appearance, and a total.

# Sets _phase_now_cpu to the user + system seconds of this shell's finished children. `times` runs in this
# shell, never in a subshell or a command substitution (those report their own, empty, children), so it
# writes to a file.
_phase_children_cpu() {
  local file
  file="${TMPDIR:-/tmp}/phase-times.$$"
  times >"$file"
  # "0m1.234s 0m0.567s" (the decimal separator the locale's): the second line is the children's.
  _phase_now_cpu="$(awk 'NR == 2 { gsub(/,/, "."); t = 0
                                   for (i = 1; i <= 2; ++i) { split($i, p, /[ms]/); t += p[1] * 60 + p[2] }
                                   printf "%.1f", t }' "$file")"
  rm -f "$file"
}

phase_start() {
  _phase_wall="${EPOCHREALTIME/,/.}"  # the locale's decimal separator, awk's is a point
  _phase_children_cpu
  _phase_cpu="$_phase_now_cpu"
}

phase_end() {  # NAME STATUS
  [ -n "${SHADOWFX_PHASE_TIMES:-}" ] || return 0
  _phase_children_cpu
  awk -v name="$1" -v status="$2" -v w0="$_phase_wall" -v w1="${EPOCHREALTIME/,/.}" -v c0="$_phase_cpu" \
    -v c1="$_phase_now_cpu" 'BEGIN { printf "%s\t%.0f\t%.1f\t%d\n", name, w1 - w0, c1 - c0, status }' \
    >>"$SHADOWFX_PHASE_TIMES"
}

phase() {  # NAME COMMAND...
  local name="$1" status=0
  shift
  phase_start
  "$@" || status=$?
  phase_end "$name" "$status"
  return "$status"
}

print_phase_times() {  # FILE
  [ -s "$1" ] || return 0
  echo "== CI time by phase (wall and CPU seconds; CPU: user + system of the phase's processes)"
  awk -F '\t' '
    !($1 in wall) { order[++n] = $1 }
    { wall[$1] += $2; cpu[$1] += $3; if ($4 != 0) failed[$1] = $4; tw += $2; tc += $3 }
    END {
      printf "%-34s %7s %8s  %s\n", "phase", "wall s", "CPU s", "status"
      for (i = 1; i <= n; ++i)
        printf "%-34s %7d %8.1f  %s\n", order[i], wall[order[i]], cpu[order[i]],
               (order[i] in failed) ? "FAILED (" failed[order[i]] ")" : "ok"
      printf "%-34s %7d %8.1f\n", "total", tw, tc
    }' "$1"
}
