#!/usr/bin/env bash
# An installed prefix works from another folder (issue 28): the layout, `ncvm run` finding
# its macros and presets, the man page and completion, and the C++ API built against the
# prefix twice: with find_package(ncvm) (examples/embed) and with pkg-config; `ncvm lsp`.
#   installed.sh PREFIX SOURCE_DIR
set -uo pipefail
prefix=$(realpath "$1") src=$(realpath "$2")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; [ -f "$tmp/out" ] && cat "$tmp/out"; exit 1; }
cd "$tmp"

# The layout.
for f in bin/ncvm bin/ncvm-serve include/ncvm/ncvm.hpp include/ncvm/job.hpp include/ncvm/events.hpp \
         include/ncvm/result.hpp lib/libncvm.so lib/cmake/ncvm/ncvmConfig.cmake \
         lib/cmake/ncvm/ncvmConfigVersion.cmake lib/cmake/ncvm/ncvmTargets.cmake \
         lib/pkgconfig/ncvm.pc share/man/man1/ncvm.1 share/bash-completion/completions/ncvm \
         share/ncvm/macros/O9135.nc share/ncvm/presets/fanuc-0i-mf.toml \
         share/ncvm/examples/macro-basics/bolt-circle.nc share/doc/ncvm/LICENSE \
         share/doc/ncvm/THIRD-PARTY-NOTICES lib/python3/dist-packages/ncvm/__init__.py; do
  [ -e "$prefix/$f" ] || fail "$f not installed"
done
ls "$prefix"/lib/python3/dist-packages/ncvm/_ncvm*.so >/dev/null 2>&1 || fail "no Python module"
if [ -d "$prefix/share/ncvm/web" ]; then
  [ -f "$prefix/share/ncvm/web/index.html" ] || fail "web assets without index.html"
  leftovers=$(find "$prefix/share/ncvm/web" -name CMakeFiles -o -name '*.cmake' -o -name Makefile)
  [ -z "$leftovers" ] || fail "build leftovers in share/ncvm/web: $leftovers"
fi
# Nothing of the build tree: no absolute path of it in the CMake package or the .pc file.
grep -rl "$src" "$prefix/lib/cmake" "$prefix/lib/pkgconfig" && fail "the package names the source tree"

# The installed command, from elsewhere: the bundled macro O9135 comes from share/ncvm/macros
# (the example calls it), the preset from share/ncvm/presets.
ex="$prefix/share/ncvm/examples"
peck=("$ex/variable-peck-o9135/o9135-call.nc" --setup fanuc-0i-tf --setup "$ex/variable-peck-o9135/setup.toml")
"$prefix/bin/ncvm" run "${peck[@]}" >"$tmp/out" 2>&1 || fail "installed ncvm run (exit $?)"
grep -q "ended: M30\|ended: M02" "$tmp/out" || fail "the example did not end normally"
mkdir -p "$tmp/no-macros"
NCVM_MACROS="$tmp/no-macros" "$prefix/bin/ncvm" run "$ex/variable-peck-o9135/o9135-call.nc" \
  --setup "$prefix/share/ncvm/presets/fanuc-0i-tf.toml" --setup "$ex/variable-peck-o9135/setup.toml" >"$tmp/out" 2>&1
[ $? = 3 ] || fail "the example ran without its macro: the test proves nothing"
# man(1) reads it from the prefix's share/man (MANPATH); groff renders it (groff-base).
[ -z "$(groff -man -ww -z "$prefix/share/man/man1/ncvm.1" 2>&1)" ] || fail "the man page does not render cleanly"

# Completion: subcommands and a subcommand's options, from the installed command's help.
complete_words() {
  PATH="$prefix/bin:$PATH" bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1));
    _ncvm; printf "%s\n" "${COMPREPLY[@]}"' _ "$prefix/share/bash-completion/completions/ncvm" "$@"
}
complete_words ncvm r | grep -qx run || fail "completion: ncvm r -> run"
complete_words ncvm run --tr | grep -qx -- --trace || fail "completion: ncvm run --tr -> --trace"
complete_words ncvm check --js | grep -qx -- --json || fail "completion: ncvm check --js -> --json"

# The C++ API: examples/embed with find_package(ncvm), built and run from here.
cmake -S "$prefix/share/ncvm/examples/embed" -B "$tmp/embed" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" \
  >"$tmp/out" 2>&1 || fail "embed: configure"
cmake --build "$tmp/embed" >"$tmp/out" 2>&1 || fail "embed: build"
"$tmp/embed/embed-ncvm" "$ex/variable-peck-o9135/o9135-call.nc" fanuc-0i-tf "$ex/variable-peck-o9135/setup.toml" \
  >"$tmp/out" 2>&1 || fail "embed: run (exit $?)"
grep -q "ended: M30\|ended: M02" "$tmp/out" || fail "embed: did not end normally"
grep -q "longest feed move" "$tmp/out" || fail "embed: no feed moves seen through the handler"
cat "$tmp/out"
printf 'G0 X1\n#1=1/0\nM30\n' >"$tmp/alarm.nc"
"$tmp/embed/embed-ncvm" "$tmp/alarm.nc" >"$tmp/out" 2>&1
[ $? = 3 ] || fail "embed: an alarm is exit 3"
grep -q "alarm.nc:2:.*PS0112" "$tmp/out" || fail "embed: the alarm line"

# The same with pkg-config and nothing else.
PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --exists ncvm || fail "pkg-config: no ncvm"
# shellcheck disable=SC2046
g++ -std=c++17 -o "$tmp/embed-pc" "$prefix/share/ncvm/examples/embed/main.cpp" \
  $(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags --libs ncvm) >"$tmp/out" 2>&1 ||
  fail "pkg-config: build"
"$tmp/embed-pc" "$ex/macro-basics/bolt-circle.nc" >"$tmp/out" 2>&1 || fail "pkg-config build: run"

# The installed language server, from elsewhere: initialize, a document whose dry run alarms
# (diagnostics from the engine), shutdown and exit, framed as an editor frames them.
frame() { printf 'Content-Length: %d\r\n\r\n%s' "${#1}" "$1"; }
{
  frame '{"jsonrpc":"2.0","id":1,"method":"initialize","params":{"processId":null,"rootUri":null,"capabilities":{}}}'
  frame '{"jsonrpc":"2.0","method":"initialized","params":{}}'
  frame '{"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":{"uri":"file:///tmp/x.nc","languageId":"fanuc","version":1,"text":"O0001\nG01 X10.\nM30\n"}}}'
  sleep 1
  frame '{"jsonrpc":"2.0","id":2,"method":"shutdown"}'
  frame '{"jsonrpc":"2.0","method":"exit"}'
} | timeout 60 "$prefix/bin/ncvm" lsp >"$tmp/out" 2>&1 || fail "installed ncvm lsp (exit $?)"
grep -q '"capabilities"' "$tmp/out" || fail "ncvm lsp: no initialize result"
grep -q 'PS0011' "$tmp/out" || fail "ncvm lsp: no diagnostic from the dry run"
echo "installed prefix: ok"
