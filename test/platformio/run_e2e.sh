#!/usr/bin/env bash
# run_e2e.sh ELF_DIR E2E_BINARY --gtest_filter=... MODEL...
# Runs the e2e suite on the ELFs in ELF_DIR (the PlatformIO build's), or
# exits 77 (skipped) when the build test made none of them.
set -euo pipefail
dir="$1" exe="$2" filter="$3"
shift 3
for model in "$@"; do
  if [ ! -f "$dir/strider_firmware_$model.elf" ]; then
    echo "skipped: no PlatformIO-built $model in $dir (see the platformio_build test)"
    exit 77
  fi
done
STRIDER_FIRMWARE_DIR="$dir" exec "$exe" "$filter"
