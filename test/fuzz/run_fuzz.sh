#!/usr/bin/env bash
# run_fuzz.sh FUZZER WORK SEEDS [libFuzzer options...]
# One bounded libFuzzer run for ctest: WORK is emptied first and takes the
# inputs the run finds (and any crash, leak or timeout input), SEEDS (a
# folder, or empty for none) is read only. Exit status: the fuzzer's.
set -euo pipefail
fuzzer=$1 work=$2 seeds=$3
shift 3
rm -rf "$work"
mkdir -p "$work/corpus"
dirs=("$work/corpus")
[ -n "$seeds" ] && dirs+=("$seeds")
exec "$fuzzer" -artifact_prefix="$work/" "$@" "${dirs[@]}"
