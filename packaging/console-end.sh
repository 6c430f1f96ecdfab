# How the console ended and what the demo stopped, said in the terminal (sourced by ./touchline;
# tested by LauncherCrashTest). Uses the caller's `say`.

# The JVM writes its crash log (hs_err) here, not into whatever directory the console started in.
CRASH_DIR=${TOUCHLINE_CRASH_DIR:-${XDG_STATE_HOME:-$HOME/.local/state}/touchline/crashes}
crash_log_option() { mkdir -p "$CRASH_DIR" 2>/dev/null || true; echo "-XX:ErrorFile=$CRASH_DIR/hs_err_pid%p.log"; }

# Runs the console (the command given, a java) in the foreground and returns its exit code; when it
# did not end normally, says so: its crash log, the signal that stopped it, or its exit code.
run_console() {
  mkdir -p "$CRASH_DIR"
  local pidfile rc=0 pid log
  pidfile=$(mktemp)
  # the subshell's process becomes the java (exec): its pid names the crash log
  ( echo "$BASHPID" >"$pidfile"; exec "$@" ) || rc=$?
  pid=$(cat "$pidfile"); rm -f "$pidfile"
  log="$CRASH_DIR/hs_err_pid$pid.log"
  if [ -f "$log" ]; then
    say "the console crashed (process $pid, exit code $rc); its crash log: $log"
  elif [ "$rc" -eq 130 ]; then
    say "the console was stopped (Ctrl+C)"
  elif [ "$rc" -gt 128 ]; then
    say "the console was killed by signal $((rc - 128)) (SIG$(kill -l $((rc - 128)) 2>/dev/null || echo '?')), process $pid; no crash log in $CRASH_DIR"
  elif [ "$rc" -ne 0 ]; then
    say "the console ended with exit code $rc (its messages are above)"
  fi
  return "$rc"
}

# Stops the processes a demo or team started (PIDS, named in PID_NAMES) and says which.
stop_team() {
  [ "${#PIDS[@]}" -gt 0 ] || return 0
  local i stopped=() gone=()
  for i in "${!PIDS[@]}"; do
    if kill "${PIDS[$i]}" 2>/dev/null; then stopped+=("${PID_NAMES[$i]:-process ${PIDS[$i]}}")
    else gone+=("${PID_NAMES[$i]:-process ${PIDS[$i]}}"); fi
  done
  [ "${#stopped[@]}" -eq 0 ] || say "stopped the simulated team: $(names "${stopped[@]}")"
  [ "${#gone[@]}" -eq 0 ] || say "had already ended: $(names "${gone[@]}") (their logs: ${TEAM_LOGS:-robot-side/build/*.log})"
  PIDS=()
  PID_NAMES=()
}

names() { local out; printf -v out '%s, ' "$@"; echo "${out%, }"; }
