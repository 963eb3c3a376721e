#!/bin/bash
# check_install.sh CMAKE BUILD VERSION: installs BUILD with `CMAKE --install BUILD --prefix P`
# into a scratch prefix P, then, from a folder outside the source and build trees, checks that
# P/bin/frix --version names VERSION, that every P/bin/frix-<script> runs (--help, exit 0, its usage naming the command;
# frix-plot-history also draws a plot from a small history file), that the Python modules are
# in P/share/frix/python and the documentation in P/share/doc/frix.
# Prints PASS:/FAIL: lines; exit 0 if all pass.
set -u
[ $# -eq 3 ] || { echo "usage: check_install.sh CMAKE BUILD VERSION" >&2; exit 2; }
cmake=$1; build=$2; version=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
failed=0
check() {  # check DESCRIPTION COMMAND...
    local what=$1; shift
    if "$@"; then echo "PASS: $what"; else echo "FAIL: $what"; failed=1; fi
}
if ! "$cmake" --install "$build" --prefix "$prefix" > "$work/install.log" 2>&1; then
    cat "$work/install.log"; echo "FAIL: cmake --install"; exit 1
fi
echo "PASS: cmake --install $build --prefix <scratch>"
cd "$work"   # not the source tree: the commands must find their modules by themselves
PATH=/usr/bin:/bin   # only the system's tools: the installed commands are called by path

check "P/bin/frix --version names $version" \
      bash -c '"$1"/bin/frix --version > version.txt && head -n 1 version.txt | grep -qx "frix $2"' _ "$prefix" "$version"
commands=$(cd "$prefix/bin" && ls frix-* 2> /dev/null)
check "postproc commands installed ($(echo $commands))" test -n "$commands"
check "frix-plot-history installed" test -x "$prefix/bin/frix-plot-history"
for command in $commands; do
    check "$command --help names $command" \
          bash -c '"$1" --help > help.txt 2>&1 && grep -q "usage: $2" help.txt' _ "$prefix/bin/$command" "$command"
done
check "the module frix_results.py is no command" test ! -e "$prefix/bin/frix-frix-results"
check "frix_results.py in P/share/frix/python" test -f "$prefix/share/frix/python/frix_results.py"
printf 'step,increment,time,u1_n3\n1,1,0.5,0.1\n1,2,1.0,0.2\n' > run_history.csv
check "frix-plot-history draws run_history.csv" \
      bash -c '"$1" run_history.csv -o curve.png > plot.log 2>&1 && test -s curve.png' _ "$prefix/bin/frix-plot-history"
check "README.md in P/share/doc/frix" test -f "$prefix/share/doc/frix/README.md"
check "docs in P/share/doc/frix/docs" test -f "$prefix/share/doc/frix/docs/deck-format.md"
[ "$failed" -eq 0 ] || cat "$work"/*.log "$work"/help.txt 2> /dev/null
exit $failed
