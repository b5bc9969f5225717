#!/usr/bin/env bash
# CPack's .deb (cmake/NcvmPackage.cmake): built from the build tree into a scratch folder,
# its installation simulated by apt, unpacked into a scratch root (dpkg-deb -x: nothing is
# installed on the machine), and run from there: the command, its data relative to its
# prefix, the Python module. Its Depends name the Debian libraries the binaries link.
#   deb.sh BUILD_DIR [PYTHON]   (with PYTHON, the interpreter the module is built for, the
#                                module is tried too)
set -uo pipefail
build=$(realpath "$1") python=${2:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; [ -f "$tmp/out" ] && tail -40 "$tmp/out"; exit 1; }
command -v dpkg-deb >/dev/null || fail "dpkg-deb missing"
cpack --config "$build/CPackConfig.cmake" -G DEB -B "$tmp/pkg" >"$tmp/out" 2>&1 || fail "cpack"
deb=$(ls "$tmp"/pkg/ncvm_*.deb 2>/dev/null | head -1)
[ -n "$deb" ] || fail "no ncvm_*.deb written"
echo "package: $(basename "$deb") ($(du -h "$deb" | cut -f1))"
dpkg-deb -f "$deb" Depends >"$tmp/depends"
grep -q "libfmt" "$tmp/depends" || { cat "$tmp/depends"; fail "Depends does not name libfmt"; }
# It would install on this Debian: apt resolves every Depends (a simulation, nothing changes).
apt-get install -s "$deb" >"$tmp/out" 2>&1 || fail "apt-get install -s: the Depends cannot be met"
grep -q "^Inst ncvm " "$tmp/out" || fail "apt-get install -s did not install ncvm"
dpkg-deb -x "$deb" "$tmp/root" || fail "dpkg-deb -x"
usr="$tmp/root/usr"
[ -x "$usr/bin/ncvm" ] || fail "no usr/bin/ncvm in the package"
[ -d "$usr/share/_CPack_Packages" ] && fail "staging folder packaged"
cd "$tmp"
"$usr/bin/ncvm" run "$usr/share/ncvm/examples/macro-basics/bolt-circle.nc" >"$tmp/out" 2>&1 ||
  fail "ncvm run from the package (exit $?)"
grep -q "ended: M30\|ended: M02" "$tmp/out" || fail "the example did not end normally"
cat "$tmp/out"
echo "Depends: $(cat "$tmp/depends")"
if [ -n "$python" ]; then
  PYTHONPATH="$usr/lib/python3/dist-packages" "$python" -c '
import ncvm, sys
r = ncvm.run(sys.argv[1])
assert r.end in ("M30", "M02"), r.end
assert len(r.moves) > 0
print("python from the package:", r)' "$usr/share/ncvm/examples/macro-basics/bolt-circle.nc" ||
    fail "the Python module from the package"
fi
echo "deb: ok"
