#!/usr/bin/env bash
# Times contact decks with two frix binaries run alternately (OLD NEW OLD NEW ...), one
# BLAS thread each, and prints one CSV row per run: the whole-process wall and CPU times
# (GNU time) and frix's own `frix: stat` split of the time (assembly, elements, contact
# search, contact kernels, factorization, solves; a binary older than that split prints
# only assembly_seconds). docs/performance-contact.md quotes its results.
#   bench/contact_speed.sh OLD_FRIX NEW_FRIX [REPEATS] DECK [DECK ...]
# REPEATS (default 1) pairs per deck. The load average before each run is in the last
# column: on a busy machine compare ratios of pairs, not single times.
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: $0 OLD_FRIX NEW_FRIX [REPEATS] DECK [DECK ...]" >&2
  exit 2
fi
old=$1
new=$2
shift 2
repeats=1
if [[ $1 =~ ^[0-9]+$ ]]; then
  repeats=$1
  shift
fi
for binary in "$old" "$new"; do
  [ -x "$binary" ] || { echo "$0: $binary is not an executable" >&2; exit 2; }
done
command -v /usr/bin/time > /dev/null || { echo "$0: needs GNU time (apt-get install time)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
keys=(newton_iterations assemblies assembly_seconds element_seconds contact_search_seconds contact_seconds
      factorize_seconds solve_seconds total_seconds)
echo "deck,binary,exit,wall_s,cpu_s,peak_mb,$(IFS=,; echo "${keys[*]}"),load"
for deck in "$@"; do
  for ((r = 1; r <= repeats; r++)); do
    for which in old new; do
      binary=$old
      [ "$which" = new ] && binary=$new
      load=$(cut -d' ' -f1 /proc/loadavg)
      status=0
      OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 /usr/bin/time -f '%e %U %S %M' -o "$work/time" \
        "$binary" "$deck" --out "$work/out" > "$work/log" 2>&1 || status=$?
      read -r wall user system peak < <(tail -1 "$work/time")
      row="$deck,$which,$status,$wall,$(awk -v u="$user" -v s="$system" 'BEGIN {print u + s}'),$((peak / 1024))"
      for key in "${keys[@]}"; do
        value=$(awk -v k="$key" '$1 == "frix:" && $2 == "stat" && $3 == k {print $4}' "$work/log")
        row="$row,${value:--}"
      done
      echo "$row,$load"
      rm -rf "$work/out"
    done
  done
done
