# The checks the service's shell tests share (sourced; $out is their output
# directory): expect runs a command and checks its exit code, said what it
# printed, fail counts a failure and shows that output.
failures=0

fail() {
  echo "FAIL: $*"
  sed 's/^/  | /' "$out/last.out" "$out/last.err"
  failures=$((failures + 1))
}
# expect CODE WHAT COMMAND...: runs COMMAND and checks its exit code.
expect() {
  local want=$1 what=$2
  shift 2
  "$@" >"$out/last.out" 2>"$out/last.err"
  local got=$?
  if [ "$got" -ne "$want" ]; then fail "$what: exit code $got, expected $want"; else echo "ok: $what"; fi
}
# said TEXT: the last command printed TEXT.
said() { grep -qF -- "$1" "$out/last.out" "$out/last.err" || fail "the output lacks: $1"; }
