#!/bin/bash
# compare.sh OLD NEW [--rel R] [--abs A] [--floor F]
#
# Compare two frix listings (docs/listing-format.md) block by block with Debian's numdiff.
#   - Lines starting with '#' and blank lines are ignored (run header, dates, paths).
#   - A block starts at a line whose first character is not a blank (its title) and runs to
#     the next such line; lines before the first title form block 0.
#   - Text fields must match exactly. Two numbers pass when
#         |new - old| <= A * (largest |real| of the OLD block)   or   |new - old| <= R * |old|
#     (numdiff -a <A*max> -r R -F 1: relative errors taken against OLD). Scaling the absolute
#     tolerance by the block's largest value lets round-off noise near zero (e.g. 1e-17 where
#     the block's displacements are 1e-3) pass, while every value still has to agree to R
#     relative to its own size or to A relative to the block. "Real" means a token with a
#     decimal point or an exponent; integer tokens (node ids, step and iteration counts) do
#     not set the scale, and with the default tolerances effectively have to match exactly.
#   - Defaults: R = 1e-6, A = 1e-9. A block whose OLD reals are all zero gets an absolute
#     tolerance of 0.
#   - --floor F: the absolute tolerance is at least F (for blocks whose values are round-off
#     around zero, such as a sum of reactions of 1e-15 where two solvers round differently).
# Exit status: 0 equal within tolerance, 1 different (the first differences are printed with
# block title and line numbers of both files), 2 usage error, missing file or missing numdiff.
set -u

usage() {
    echo "usage: compare.sh OLD NEW [--rel R] [--abs A] [--floor F]   (defaults: --rel 1e-6 --abs 1e-9 --floor 0)" >&2
    exit 2
}

rel=1e-6
abs=1e-9
floor=0
files=()
while [ $# -gt 0 ]; do
    case "$1" in
        --rel) [ $# -ge 2 ] || usage; rel=$2; shift 2 ;;
        --abs) [ $# -ge 2 ] || usage; abs=$2; shift 2 ;;
        --floor) [ $# -ge 2 ] || usage; floor=$2; shift 2 ;;
        -h | --help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
        -*) echo "compare.sh: unknown option $1" >&2; usage ;;
        *) files+=("$1"); shift ;;
    esac
done
[ ${#files[@]} -eq 2 ] || usage
old=${files[0]}
new=${files[1]}
for value in "$rel" "$abs" "$floor"; do
    if ! awk -v v="$value" 'BEGIN { exit !(v ~ /^[+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?$/) }'; then
        echo "compare.sh: tolerance '$value' is not a non-negative number" >&2
        exit 2
    fi
done
for file in "$old" "$new"; do
    if [ ! -f "$file" ] || [ ! -r "$file" ]; then
        echo "compare.sh: cannot read '$file'" >&2
        exit 2
    fi
done
if ! command -v numdiff > /dev/null; then
    echo "compare.sh: numdiff not found (Debian package numdiff)" >&2
    exit 2
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# split FILE TAG: writes $work/TAG.<n> (block n), $work/TAG.<n>.lines (the original line
# number of each of its lines), $work/TAG.<n>.scale (largest |real|), $work/TAG.titles
# ("<n> <first line> <title>" per block) and prints the number of blocks.
split_blocks() {
    awk -v prefix="$work/$2" '
        function flush_block() {
            if (n < 0) return
            printf "%.17g\n", scale > (prefix "." n ".scale")
            close(prefix "." n); close(prefix "." n ".lines"); close(prefix "." n ".scale")
        }
        function start_block(title) {
            flush_block()
            n++
            scale = 0
            printf "%d %d %s\n", n, FNR, title > (prefix ".titles")
            printf "" > (prefix "." n)
            printf "" > (prefix "." n ".lines")
        }
        BEGIN { n = -1 }
        /^#/ || /^[ \t]*$/ { next }
        /^[^ \t]/ { start_block($0) }
        n < 0 { start_block("(lines before the first block title)") }
        {
            print > (prefix "." n)
            print FNR > (prefix "." n ".lines")
            for (i = 1; i <= NF; i++) {
                if ($i ~ /^[+-]?([0-9]+\.[0-9]*|\.[0-9]+|[0-9]+)([eEdD][+-]?[0-9]+)?$/ && $i ~ /[.eEdD]/) {
                    token = $i
                    gsub(/[dD]/, "e", token)
                    value = token + 0
                    if (value < 0) value = -value
                    if (value > scale) scale = value
                }
            }
        }
        END { flush_block(); if (n < 0) printf "" > (prefix ".titles"); print n + 1 }
    ' "$1"
}

old_count=$(split_blocks "$old" old)
new_count=$(split_blocks "$new" new)
status=0
if [ "$old_count" -ne "$new_count" ]; then
    echo "compare.sh: OLD has $old_count blocks, NEW has $new_count"
    status=1
fi

shown=0      # failing blocks printed so far
max_shown=5  # keep the report short: the first differences are what one needs
failed=0
count=$((old_count < new_count ? old_count : new_count))
for ((n = 0; n < count; n++)); do
    scale=$(cat "$work/old.$n.scale")
    block_abs=$(awk -v a="$abs" -v s="$scale" -v f="$floor" 'BEGIN { t = a * s; if (t < f) t = f; printf "%.10e", t }')
    scale_text=$(awk -v s="$scale" 'BEGIN { printf "%.6g", s }')
    numdiff -a "$block_abs" -r "$rel" -F 1 "$work/old.$n" "$work/new.$n" > "$work/report" 2>&1
    result=$?
    [ $result -eq 0 ] && continue
    if [ $result -ne 1 ]; then
        echo "compare.sh: numdiff failed on block $n:" >&2
        cat "$work/report" >&2
        exit 2
    fi
    failed=$((failed + 1))
    status=1
    [ $shown -ge $max_shown ] && continue
    shown=$((shown + 1))
    title=$(awk -v n="$n" '$1 == n { $1 = ""; $2 = ""; sub(/^  /, ""); print; exit }' "$work/old.titles")
    echo "block $n \"$title\": differs (tolerances: abs $block_abs = $abs x block max $scale_text, rel $rel)"
    # numdiff numbers lines within the block; translate them to lines of OLD and NEW.
    awk -v old_map="$work/old.$n.lines" -v new_map="$work/new.$n.lines" '
        BEGIN {
            while ((getline line < old_map) > 0) old_line[++i] = line
            i = 0
            while ((getline line < new_map) > 0) new_line[++i] = line
        }
        /^##[0-9]+/ {
            k = substr($1, 3) + 0
            field = ""
            if ($2 ~ /^#[:>]/) field = ", field " substr($2, 3)
            if (index($0, "<==") > 0) { sub(/.*<== ?/, ""); print "  OLD line " old_line[k] field ": " $0; next }
            if (index($0, "==>") > 0) { sub(/.*==> ?/, ""); print "  NEW line " new_line[k] field ": " $0; next }
        }
        /^@/ { sub(/^@ */, "  "); sub(/ *@@ *$/, ""); if ($0 !~ /^ *$/) print; next }
        /^\+\+\+/ || /^-+$/ || /^ *$/ { next }
        { print "  " $0 }
    ' "$work/report" | head -n 40
done

if [ $status -eq 0 ]; then
    echo "compare.sh: equal within tolerance ($count blocks; rel $rel, abs $abs x block max)"
else
    [ $failed -gt $shown ] && echo "... and $((failed - shown)) more differing blocks"
    echo "compare.sh: OLD and NEW differ ($failed of $count compared blocks)"
fi
exit $status
