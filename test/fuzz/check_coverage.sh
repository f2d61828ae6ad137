#!/usr/bin/env bash
# check_coverage.sh FUZZER PROFDATA COV WORK DICT SEEDS DICT_RUNS SEED_RUNS FILE:MIN_DICT:MIN_SEEDS...
# Whether a libFuzzer target reaches the code it is for. FUZZER is built
# with -fprofile-instr-generate -fcoverage-mapping; it runs twice with
# -seed=1, each from an empty corpus folder:
#   dictionary  DICT_RUNS runs with the dictionary DICT alone;
#   seeds       SEED_RUNS runs with DICT and the seed corpus SEEDS (as ctest's
#               fuzz run starts).
# After each run, llvm-cov's line coverage of every FILE must reach its
# minimum [%] for that run (MIN_DICT, MIN_SEEDS). Prints the coverage; exit
# status 1 when a file falls short.
set -euo pipefail
fuzzer=$1 profdata=$2 cov=$3 work=$4 dict=$5 seeds=$6 dict_runs=$7 seed_runs=$8
shift 8
files=("$@")
rm -rf "$work"
mkdir -p "$work"
status=0

# run NAME RUNS COLUMN [corpus folders...]: COLUMN 2 or 3 of FILE:MIN_DICT:MIN_SEEDS.
run() {
  local name=$1 runs=$2 column=$3
  shift 3
  mkdir -p "$work/$name/corpus"
  LLVM_PROFILE_FILE="$work/$name.profraw" "$fuzzer" -runs="$runs" -seed=1 -dict="$dict" \
    -artifact_prefix="$work/$name/" "$work/$name/corpus" "$@" >"$work/$name.log" 2>&1 || {
    cat "$work/$name.log"
    echo "$name: the fuzzer failed"
    status=1
    return
  }
  "$profdata" merge -sparse "$work/$name.profraw" -o "$work/$name.profdata"
  local spec file min line
  for spec in "${files[@]}"; do
    file=${spec%%:*}
    min=$(echo "$spec" | cut -d: -f"$column")
    # llvm-cov report of one file, its TOTAL row: Regions Missed Cover
    # Functions Missed Executed Lines Missed Cover ...
    line=$("$cov" report "$fuzzer" -instr-profile="$work/$name.profdata" "$file" |
      awk '$1 == "TOTAL" { sub("%", "", $10); print $10 }')
    [ -n "$line" ] || line=0
    if awk -v c="$line" -v m="$min" 'BEGIN { exit !(c + 0 >= m + 0) }'; then
      echo "$name ($runs runs): $(basename "$file") lines ${line}% (minimum ${min}%)"
    else
      echo "$name ($runs runs): $(basename "$file") lines ${line}% BELOW the minimum ${min}%"
      status=1
    fi
  done
}

run dictionary "$dict_runs" 2
run seeds "$seed_runs" 3 "$seeds"
exit "$status"
