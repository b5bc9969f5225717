#!/usr/bin/env bash
# `ncvm serve` as a command: it listens on 127.0.0.1 unless told otherwise, prints its URL,
# opens PROGRAM, refuses a port in use (exit 2), a missing --root and a bad --setup; and its
# worker answers a malformed request with an error, not a crash; the server is ncvm-serve.
set -u
ncvm=$1
dir=$2
tmp=$(mktemp -d)
pid=""
cleanup() {
  [ -n "$pid" ] && kill "$pid" 2>/dev/null && wait "$pid" 2>/dev/null
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$ncvm" serve --port 0 "$dir/ok.nc" >"$tmp/out" 2>"$tmp/err" &
pid=$!
for _ in $(seq 1 100); do grep -q 'http://' "$tmp/out" && break; sleep 0.1; done
url=$(grep -o 'http://[^ ]*/' "$tmp/out") || fail "no URL printed: $(cat "$tmp/out" "$tmp/err")"
case "$url" in http://127.0.0.1:*/) ;; *) fail "not on 127.0.0.1 by default: $url" ;; esac
port=${url#http://127.0.0.1:}
port=${port%/}
# The listening socket is bound to loopback only.
if command -v ss >/dev/null; then
  ss -ltn | grep -q "127.0.0.1:$port " || fail "not listening on 127.0.0.1:$port"
  ss -ltn | grep -qE "(0\.0\.0\.0|\*|\[::\]):$port " && fail "listening on all addresses"
fi
info=$(python3 -c "import urllib.request,sys; print(urllib.request.urlopen(sys.argv[1] + 'api/info', timeout=10).read().decode())" "$url") ||
  fail "GET /api/info"
echo "$info" | grep -q '"path":"ok.nc"' || fail "PROGRAM not offered as the start file: $info"

timeout 10 "$ncvm" serve --port "$port" >"$tmp/out2" 2>"$tmp/err2"; rc=$?
[ $rc = 2 ] || fail "a second server on port $port: exit $rc"
grep -q "cannot bind" "$tmp/err2" || fail "port in use message: $(cat "$tmp/err2")"

"$ncvm" serve --port 0 --root "$tmp/missing" >/dev/null 2>"$tmp/err3"; rc=$?
[ $rc = 2 ] || fail "missing --root: exit $rc"
printf '[machine\n' >"$tmp/bad.toml"
"$ncvm" serve --port 0 --setup "$tmp/bad.toml" >/dev/null 2>"$tmp/err4"; rc=$?
[ $rc = 2 ] || fail "bad --setup: exit $rc"

answer=$(printf '{not json' | "$ncvm" serve-worker) || fail "worker exit $? on a malformed request"
echo "$answer" | grep -q '"ok":false' || fail "worker answer: $answer"
answer=$(printf '{"program":"O1\\nG00 X1.\\nM30\\n"}' | "$ncvm" serve-worker) || fail "worker exit $?"
echo "$answer" | grep -q '"ok":true' || fail "worker answer: $answer"
# The HTTP server is ncvm-serve, beside ncvm: ncvm itself does not load the HTTP library
# (nor OpenSSL), which would cost every other command's start-up.
[ -x "$(dirname "$ncvm")/ncvm-serve" ] || fail "no ncvm-serve beside $ncvm"
if command -v readelf >/dev/null; then
  readelf -d "$ncvm" | grep -E 'NEEDED.*(httplib|libssl|libcrypto)' && fail "ncvm loads the HTTP library"
fi
echo "serve: ok"
