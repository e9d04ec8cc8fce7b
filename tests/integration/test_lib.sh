# Sourced by the integration test scripts: a scratch folder removed on exit (KEEP=1 keeps it and
# says where), the checks ("ok - ..." / "not ok - ..." and a final "N passed, M failed"), local
# HTTP without proxies, and starting one of our fake servers on an ephemeral port.
#   ok NAME | bad NAME | check NAME 'CONDITION' | finish (prints the tally, exits 0 if all passed)
#   start_server SCRIPT ARGS...   runs SCRIPT PORT_FILE ARGS... in the background; sets
#                                 server_pid and port, or returns 1 if no port appeared in 5 s
#   closed_port                   prints a local port nothing listens on (for "refused")
py=/usr/bin/python3
[[ -x $py ]] || py=python3
tmp=$(mktemp -d)
server_pid=
port=
cleanup() {
  if [[ -n $server_pid ]]; then kill "$server_pid" 2>/dev/null; wait "$server_pid" 2>/dev/null; fi
  [[ -n ${KEEP:-} ]] && echo "kept $tmp" || rm -rf "$tmp"
}
trap cleanup EXIT
pass=0 fail=0
ok() { echo "ok - $1"; pass=$((pass + 1)); }
bad() { echo "not ok - $1"; fail=$((fail + 1)); }
check() { if eval "$2"; then ok "$1"; else bad "$1"; fi; }
finish() { echo "$pass passed, $fail failed"; [[ $fail -eq 0 ]]; exit; }

# The fake servers are local: no proxy may stand in between.
unset http_proxy https_proxy HTTP_PROXY HTTPS_PROXY all_proxy ALL_PROXY
export no_proxy=127.0.0.1,localhost NO_PROXY=127.0.0.1,localhost

start_server() {
  local script=$1; shift
  "$py" "$script" "$tmp/port" "$@" &
  server_pid=$!
  for _ in $(seq 50); do [[ -s $tmp/port ]] && break; sleep 0.1; done
  [[ -s $tmp/port ]] || return 1
  port=$(cat "$tmp/port")
}

# Bind an ephemeral port, then release it.
closed_port() {
  "$py" -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()'
}
