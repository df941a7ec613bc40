# The one way the integration scripts start a process in the background and wait for it.
# POSIX sh, sourced:   . "$(dirname "$0")/lib.sh"
#
#   $dir                        a fresh temporary directory; on exit (or SIGINT/SIGTERM/SIGHUP)
#                               every process started with bg_start still running is ended
#                               and $dir is removed
#   bg_start NAME CMD [ARG...]  runs CMD in the background with stdout in $dir/NAME.out and
#                               stderr in $dir/NAME.err, both created before it starts (a
#                               reader never finds them missing); its pid in $bg_pid
#   bg_await NAME.out|NAME.err PATTERN [SECONDS]
#                               waits until a line of that file matches PATTERN (grep basic
#                               regular expression); fails (exit 1, every started process's
#                               files shown) when SECONDS (default 30) pass or NAME ends first
#   bg_stop NAME [SIGNAL]       sends SIGNAL (default TERM) to NAME and waits for its end
#   bg_signal NAME SIGNAL       sends SIGNAL to NAME, which goes on running
#   bg_wait NAME                waits for NAME to end by itself
#                               (both: the exit status in $bg_rc, NAME no longer ended on exit)
# The functions work under `set -e` and `set -u`.
#   bg_fail MESSAGE             prints MESSAGE and every started process's files, exit 1
#   ended_ok WHAT RC ERRFILE    unless RC is 0: "WHAT exited with RC", ERRFILE shown, exit 1
#
# NAME is a shell identifier (run, master, echo, ...). The deadline is a limit for a loaded
# machine, not a delay: the wait ends as soon as the line is there.

# shellcheck disable=SC2034  # dir, bg_pid, bg_rc: for the sourcing script
dir=$(mktemp -d)
bg_names=

bg_cleanup() {
  for _bg_n in $bg_names; do
    eval "_bg_p=\${bg_pid_$_bg_n:-}"
    if [ -n "$_bg_p" ]; then
      kill "$_bg_p" 2>/dev/null || :
      wait "$_bg_p" 2>/dev/null || :
    fi
  done
  rm -rf "$dir"
}
trap bg_cleanup EXIT
# A signal (ctest's timeout, Ctrl-C) ends the script through the EXIT trap above.
trap 'exit 129' HUP
trap 'exit 130' INT
trap 'exit 143' TERM

bg_dump() {
  for _bg_n in $bg_names; do
    for _bg_f in "$dir/$_bg_n.out" "$dir/$_bg_n.err"; do
      echo "--- $(basename "$_bg_f")"
      cat "$_bg_f" 2>/dev/null
    done
  done
}

bg_fail() {
  echo "FAIL: $*"
  bg_dump
  exit 1
}

bg_start() {
  _bg_n=$1
  shift
  : >"$dir/$_bg_n.out"
  : >"$dir/$_bg_n.err"
  "$@" >"$dir/$_bg_n.out" 2>"$dir/$_bg_n.err" &
  bg_pid=$!
  eval "bg_pid_$_bg_n=\$bg_pid"
  case " $bg_names " in *" $_bg_n "*) ;; *) bg_names="$bg_names $_bg_n" ;; esac
}

bg_await() {
  _bg_file=$1
  _bg_pattern=$2
  _bg_limit=${3:-30}
  _bg_n=${_bg_file%.*}
  eval "_bg_p=\${bg_pid_$_bg_n:-}"
  _bg_end=$(($(date +%s) + _bg_limit))
  while ! grep -q -- "$_bg_pattern" "$dir/$_bg_file"; do
    if [ -z "$_bg_p" ] || ! kill -0 "$_bg_p" 2>/dev/null; then
      # ended: the line may have come just before the end
      grep -q -- "$_bg_pattern" "$dir/$_bg_file" && return 0
      [ -n "$_bg_p" ] && bg_wait "$_bg_n"
      bg_fail "$_bg_n ended (exit ${bg_rc:-?}) before a line matching '$_bg_pattern' in $_bg_file"
    fi
    [ "$(date +%s)" -lt "$_bg_end" ] ||
      bg_fail "no line matching '$_bg_pattern' in $_bg_file within ${_bg_limit} s"
    sleep 0.05  # the poll interval
  done
}

bg_stop() {
  eval "_bg_p=\${bg_pid_$1:-}"
  [ -n "$_bg_p" ] || bg_fail "bg_stop $1: not running"
  kill -s "${2:-TERM}" "$_bg_p" || :  # ended already: bg_wait gives its status
  bg_wait "$1"
}

bg_signal() {
  eval "_bg_p=\${bg_pid_$1:-}"
  [ -n "$_bg_p" ] || bg_fail "bg_signal $1: not running"
  kill -s "$2" "$_bg_p" || bg_fail "bg_signal $1 $2: it has ended"
}

bg_wait() {
  eval "_bg_p=\${bg_pid_$1:-}"
  [ -n "$_bg_p" ] || bg_fail "bg_wait $1: not running"
  bg_rc=0
  wait "$_bg_p" || bg_rc=$?
  eval "bg_pid_$1="
}

ended_ok() {
  if [ "$2" -ne 0 ]; then
    echo "$1 exited with $2"
    cat "$3"
    exit 1
  fi
}
