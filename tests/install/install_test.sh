#!/usr/bin/env bash
# clumpkit as a library and a package, from a built tree:
# 1. `cmake --install` into a prefix: exactly the public headers (the list CMake wrote), each
#    compiling alone (tests/install/headers), and examples/cpp configured against the prefix,
#    built and run: its union volume equals `clumpkit volume`'s to the printed digits;
# 2. the Debian package (cpack): Depends computed for the runtime libraries, and its files
#    extracted (dpkg-deb -x) run `clumpkit --version`, `clumpkit fill` and `import clumpkit`.
#   tests/install/install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(realpath "$1")
src=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
jobs=$(nproc 2>/dev/null || echo 2)
fail() { echo "install_test: $*" >&2; exit 1; }

prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
(cd "$prefix/include/clumpkit" && find . -name '*.h' | sed 's|^\./||' | sort) >"$work/installed.txt"
sort "$build/public_headers.txt" >"$work/public.txt"
diff -u "$work/public.txt" "$work/installed.txt" || fail "installed headers differ from the public set"
echo "installed: $(wc -l <"$work/installed.txt") public headers, $(ls "$prefix"/lib/clumpkit) "

cmake -S "$src/tests/install/headers" -B "$work/headers" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/headers" -j"$jobs" >/dev/null || fail "a public header does not compile alone"
echo "each public header compiles alone"

cmake -S "$src/examples/cpp" -B "$work/example" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/example" -j"$jobs" >/dev/null
"$prefix/bin/clumpkit" shape block --L 75.1 --W 58.0 --H 49.8 --seed 1 -o "$work/block.stl" >/dev/null
line=$("$work/example/fill_volume" "$work/block.stl" 30 "$work/clump.csv")
echo "examples/cpp: $line"
ours=${line##*union volume }
cli=$("$prefix/bin/clumpkit" volume "$work/clump.csv" | sed -n 's/^ *exact *volume \([^ ]*\).*/\1/p')
[ -n "$cli" ] || fail "no exact volume in: $("$prefix/bin/clumpkit" volume "$work/clump.csv")"
[ "$ours" = "$cli" ] || fail "volume $ours (examples/cpp) != $cli (clumpkit volume)"
echo "clumpkit volume: $cli (the same digits)"

cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/pkg" >/dev/null
deb=$(ls "$work"/pkg/clumpkit_*.deb)
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for lib in libtbb libopencv-core libembree libopenvdb libstdc++6 python3-numpy libjs-three; do
  case "$depends" in *"$lib"*) ;; *) fail "Depends lacks $lib" ;; esac
done
root=$work/root
dpkg-deb -x "$deb" "$root"
"$root/usr/bin/clumpkit" --version | tee "$work/version.txt"
grep -q "^clumpkit $("$build/io/clumpkit" --version | head -1 | cut -d' ' -f2) " "$work/version.txt" ||
  fail "--version of the package differs from the build's"
"$root/usr/bin/clumpkit" fill "$work/block.stl" -o "$work/deb-clump.csv" --spheres 30 >/dev/null
[ -s "$work/deb-clump.csv" ] || fail "the packaged clumpkit fill wrote nothing"
[ -f "$root/usr/share/man/man1/clumpkit-fill.1" ] || fail "no man page clumpkit-fill.1"
v=$(cd "$work" && PYTHONPATH="$root/usr/lib/python3/dist-packages" /usr/bin/python3 -c \
  'import clumpkit; print(clumpkit.__version__, clumpkit.__file__)')
echo "python: $v"
case "$v" in *"$root"*) ;; *) fail "import clumpkit did not load the packaged module: $v" ;; esac
echo "install_test: passed"
