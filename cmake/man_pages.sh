#!/usr/bin/env bash
# Writes OUT/clumpkit.1 and OUT/clumpkit-COMMAND.1 for every command `clumpkit --help` lists,
# from the program's --help (help2man).
#   cmake/man_pages.sh CLUMPKIT OUT VERSION
set -euo pipefail
bin=$(realpath "$1")
out=$2
version=$3
mkdir -p "$out/bin"
h2m=(help2man --no-info --no-discard-stderr --version-string="$version")
commands=$("$bin" --help | sed -n '/^Subcommands:/,$p' | sed -n 's/^  \([a-z][a-z-]*\) .*/\1/p')
for c in $commands; do
  # help2man runs one program: a wrapper runs `clumpkit COMMAND`.
  printf '#!/bin/sh\nexec "%s" %s "$@"\n' "$bin" "$c" >"$out/bin/clumpkit-$c"
  chmod +x "$out/bin/clumpkit-$c"
  "${h2m[@]}" --name "clumpkit $c" --output "$out/clumpkit-$c.1" "$out/bin/clumpkit-$c"
  # The page names the command as users type it, not the wrapper's path.
  sed -i "s|$out/bin/clumpkit-$c|clumpkit $c|g; s|clumpkit\\\\-$c|clumpkit $c|g" "$out/clumpkit-$c.1"
done
"${h2m[@]}" --name "irregular particles, sphere clumps and DEM specimens for geomaterials" \
  --output "$out/clumpkit.1.tmp" "$bin"
sed -i "s|$bin|clumpkit|g" "$out/clumpkit.1.tmp"
mv "$out/clumpkit.1.tmp" "$out/clumpkit.1"
