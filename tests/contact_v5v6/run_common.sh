# Shared by run_v5.sh and run_v6.sh (sourced): run_in_scratch SCRIPT FRIX DECK runs frix on DECK
# in a fresh scratch folder (removed on exit), stops with the tail of frix's output if it fails,
# and prints the run time. Sets `work` (the folder, with run.log) and `name` (the deck's base name).
run_in_scratch() {
    local script=$1 frix=$2 deck=$3 start
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
    name=$(basename "$deck" .dck)
    start=$(date +%s.%N)
    if ! "$frix" "$deck" --out "$work" > "$work/run.log" 2>&1; then
        echo "$script: frix failed on $deck:"; grep -v '^  step' "$work/run.log" | tail -n 20; exit 1
    fi
    awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "run time %.2f s\n", e - s }'
}
