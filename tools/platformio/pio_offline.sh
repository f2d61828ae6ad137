#!/usr/bin/env bash
# Builds firmware environments of platformio.ini with PlatformIO itself, as
# users do (`pio run -e <model>`), into the build tree:
#   tools/platformio/pio_offline.sh [env ...]      (default: all five models)
# Usually run as `tools/dev pio [env ...]`. Environment:
#   STRIDER_THIRD_PARTY  the pinned upstream trees (platform-atmelavr,
#                        ArduinoCore-avr, the Adafruit libraries): when set,
#                        nothing comes from PlatformIO's registry; PlatformIO
#                        gets local packages (Debian's avr-gcc as its toolchain)
#                        through an extra ini and environment variables only.
#                        Empty or unset: plain `pio run` against the registry.
#   STRIDER_BUILD_DIR    the build tree (out/build); everything goes to <it>/pio
#   STRIDER_VENV         the venv PlatformIO is installed into (out/venv)
#   STRIDER_JOBS         parallel compile jobs
# Output: <build>/pio/elf/strider_firmware_<env>.elf and .hex (the CMake
# build's names), and avr-size of each. Exit 77 when it cannot run here (no
# PlatformIO from PyPI, or no third_party and no registry): tests skip.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD="${STRIDER_BUILD_DIR:-$ROOT/out/build}"
mkdir -p "$BUILD"
BUILD="$(cd "$BUILD" && pwd)"
VENV="${STRIDER_VENV:-$ROOT/out/venv}"
JOBS="${STRIDER_JOBS:-$(nproc 2>/dev/null || echo 2)}"
THIRD_PARTY="${STRIDER_THIRD_PARTY:-}"

PIO_VERSION=6.2.0
SCONS_VERSION=4.11.1          # PlatformIO 6.2.0 wants tool-scons ~4.41101.0
SCONS_PACKAGE_VERSION=4.41101.0
PWM_LIB="Adafruit PWM Servo Driver Library"
PWM_LIB_VERSION=3.0.2         # its library.properties still says 3.0.1
BUSIO_LIB="Adafruit BusIO"
BUSIO_LIB_VERSION=1.17.4
FRAMEWORK_VERSION=1.8.8       # ArduinoCore-avr
TOOLCHAIN_VERSION=1.50400.0   # Debian's avr-gcc 5.4.0
ALL_ENVS=(sprawl8 mammal8 dog12 hexapod18 spider12)

PIO_DIR="$BUILD/pio"
ELF_DIR="$PIO_DIR/elf"
ENVS=("$@")
[ "${#ENVS[@]}" -gt 0 ] || ENVS=("${ALL_ENVS[@]}")

log() { printf '[pio] %s\n' "$*" >&2; }
skip() { printf '[pio] skipped: %s\n' "$*"; exit 77; }

# One run at a time per build tree (tools/dev pio and the test share it).
mkdir -p "$ELF_DIR"
exec 9>"$PIO_DIR/.lock"
flock 9
# Stale ELFs of these environments never outlive a run that did not make them.
for env in "${ENVS[@]}"; do
  rm -f "$ELF_DIR/strider_firmware_$env.elf" "$ELF_DIR/strider_firmware_$env.hex"
done

# --- PlatformIO Core from PyPI, into the project's venv -----------------------
PY="$VENV/bin/python"
PIO="$VENV/bin/pio"
pio_version() { "$PIO" --version 2>/dev/null | sed -n 's/.*version \([0-9.]*\).*/\1/p'; }
if [ "$(pio_version)" != "$PIO_VERSION" ]; then
  log "installing platformio==$PIO_VERSION into $VENV"
  { [ -x "$PY" ] || python3 -m venv "$VENV"; } &&
    "$PY" -m pip install -q --disable-pip-version-check "platformio==$PIO_VERSION" ||
    skip "could not install platformio==$PIO_VERSION from PyPI"
fi

export PLATFORMIO_SETTING_ENABLE_TELEMETRY=no
export PLATFORMIO_DISABLE_UPGRADE_CHECK=true
export PLATFORMIO_DISABLE_PROGRESSBAR=true
export PLATFORMIO_RUN_JOBS="$JOBS"

if [ -z "$THIRD_PARTY" ]; then
  # --- With a network: PlatformIO's registry, as users have it --------------
  MODE=registry
  export PLATFORMIO_CORE_DIR="$PIO_DIR/registry/core"
  export PLATFORMIO_WORKSPACE_DIR="$PIO_DIR/registry/workspace"
  export PLATFORMIO_BUILD_DIR="$PLATFORMIO_WORKSPACE_DIR/build"
  export PLATFORMIO_LIBDEPS_DIR="$PLATFORMIO_WORKSPACE_DIR/libdeps"
  export PLATFORMIO_BUILD_CACHE_DIR="$PIO_DIR/registry/cache"
  if ! compgen -G "$PLATFORMIO_CORE_DIR/platforms/atmelavr*" >/dev/null &&
     ! "$PY" -c 'import socket; socket.create_connection(("api.registry.platformio.org", 443), 10).close()' 2>/dev/null; then
    skip "no STRIDER_THIRD_PARTY (pinned upstream trees) and PlatformIO's registry is unreachable"
  fi
  PIO_RUN=("$PIO" run -d "$ROOT")
else
  # --- Offline: local packages from the pinned trees and Debian -------------
  MODE=offline
  for d in platform-atmelavr ArduinoCore-avr Adafruit-PWM-Servo-Driver-Library Adafruit_BusIO; do
    [ -d "$THIRD_PARTY/$d" ] || skip "$THIRD_PARTY has no $d"
  done
  command -v avr-gcc >/dev/null && command -v avr-g++ >/dev/null ||
    skip "no avr-gcc (apt-get install gcc-avr avr-libc binutils-avr)"
  AVR_BIN="$(dirname "$(command -v avr-gcc)")"
  OFF="$PIO_DIR/offline"
  export PLATFORMIO_CORE_DIR="$OFF/core"
  export PLATFORMIO_WORKSPACE_DIR="$OFF/workspace"
  export PLATFORMIO_BUILD_DIR="$PLATFORMIO_WORKSPACE_DIR/build"
  export PLATFORMIO_LIBDEPS_DIR="$PLATFORMIO_WORKSPACE_DIR/libdeps"
  export PLATFORMIO_BUILD_CACHE_DIR="$OFF/cache"
  # avr-gcc 5.4 has no DECIMAL_DIG, which the core's WString.cpp uses
  export PLATFORMIO_BUILD_FLAGS="-DDECIMAL_DIG=__DECIMAL_DIG__"
  PKGS="$OFF/packages"          # the symlinked toolchain and the framework
  LIBDEPS="$PLATFORMIO_LIBDEPS_DIR"

  # The packages are remade when the pins or a folder change.
  stamp_want="$ROOT $OFF $THIRD_PARTY $PIO_VERSION $SCONS_VERSION $PWM_LIB_VERSION $BUSIO_LIB_VERSION $FRAMEWORK_VERSION $TOOLCHAIN_VERSION $AVR_BIN"
  if [ "$(cat "$OFF/.stamp" 2>/dev/null)" != "$stamp_want" ]; then
    log "making local PlatformIO packages in $OFF"
    rm -rf "$OFF"
    mkdir -p "$PKGS" "$PLATFORMIO_CORE_DIR/packages"

    # Platform: installed from a writable copy (the shared tree is read-only).
    cp -r --no-preserve=mode "$THIRD_PARTY/platform-atmelavr" "$PKGS/platform-atmelavr"
    "$PIO" pkg install -g --skip-dependencies -p "file://$PKGS/platform-atmelavr" >&2

    # Toolchain: Debian's avr-gcc as toolchain-atmelavr (symlinks).
    mkdir -p "$PKGS/toolchain-atmelavr/bin"
    for f in "$AVR_BIN"/avr-*; do ln -s "$f" "$PKGS/toolchain-atmelavr/bin/"; done
    cat >"$PKGS/toolchain-atmelavr/package.json" <<EOF
{"name": "toolchain-atmelavr", "version": "$TOOLCHAIN_VERSION",
 "description": "Debian's avr-gcc, avr-libc and binutils-avr (symlinks)"}
EOF

    # Framework: ArduinoCore-avr as framework-arduino-avr.
    cp -r --no-preserve=mode "$THIRD_PARTY/ArduinoCore-avr" "$PKGS/framework-arduino-avr"
    cat >"$PKGS/framework-arduino-avr/package.json" <<EOF
{"name": "framework-arduino-avr", "version": "$FRAMEWORK_VERSION",
 "description": "ArduinoCore-avr $FRAMEWORK_VERSION"}
EOF

    # SCons from PyPI as PlatformIO's tool-scons (owner platformio, or
    # PlatformIO does not recognise it and asks its registry).
    scons_dir="$PLATFORMIO_CORE_DIR/packages/tool-scons"
    "$PY" -m pip install -q --disable-pip-version-check --no-deps --target "$scons_dir" \
      "scons==$SCONS_VERSION" || skip "could not install scons==$SCONS_VERSION from PyPI"
    cat >"$scons_dir/scons.py" <<'EOF'
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from SCons.Script import main
main()
EOF
    cat >"$scons_dir/package.json" <<EOF
{"name": "tool-scons", "version": "$SCONS_PACKAGE_VERSION", "description": "SCons $SCONS_VERSION from PyPI"}
EOF
    cat >"$scons_dir/.piopm" <<EOF
{"type": "tool", "name": "tool-scons", "version": "$SCONS_PACKAGE_VERSION",
 "spec": {"owner": "platformio", "id": null, "name": "tool-scons", "requirements": null, "uri": null}}
EOF

    # The extra ini: the project's platformio.ini, plus the local packages.
    # platformio.ini is read after this file and wins, so only options it
    # does not set can be given here.
    cat >"$OFF/offline.ini" <<EOF
; Made by tools/platformio/pio_offline.sh: the project's platformio.ini with
; local packages instead of PlatformIO's registry.
[platformio]
extra_configs = $ROOT/platformio.ini

[env]
platform_packages =
    platformio/toolchain-atmelavr@symlink://$PKGS/toolchain-atmelavr
    platformio/framework-arduino-avr@symlink://$PKGS/framework-arduino-avr
EOF
    echo "$stamp_want" >"$OFF/.stamp"
  fi

  # Libraries: what the registry would install for lib_deps, each with the
  # .piopm the registry writes (owner adafruit and the version), so that
  # `adafruit/Adafruit PWM Servo Driver Library@^3.0.2` and its dependency
  # Adafruit BusIO count as installed.
  put_lib() {  # env folder name version
    local dest="$LIBDEPS/$1/$3"
    [ -f "$dest/.piopm" ] && return 0
    rm -rf "$dest"
    mkdir -p "$LIBDEPS/$1"
    cp -r --no-preserve=mode "$THIRD_PARTY/$2" "$dest"
    cat >"$dest/.piopm" <<EOF
{"type": "library", "name": "$3", "version": "$4",
 "spec": {"owner": "adafruit", "id": null, "name": "$3", "requirements": null, "uri": null}}
EOF
  }
  for env in "${ENVS[@]}"; do
    put_lib "$env" Adafruit-PWM-Servo-Driver-Library "$PWM_LIB" "$PWM_LIB_VERSION"
    put_lib "$env" Adafruit_BusIO "$BUSIO_LIB" "$BUSIO_LIB_VERSION"
  done

  PIO_RUN=("$PIO" run -d "$ROOT" -c "$OFF/offline.ini")
fi

# --- Build ---------------------------------------------------------------------
env_args=()
for env in "${ENVS[@]}"; do env_args+=(-e "$env"); done
log "$MODE: pio run ${env_args[*]} (PlatformIO $PIO_VERSION, output in $PIO_DIR)"
start=$(date +%s)
"${PIO_RUN[@]}" "${env_args[@]}"
log "pio run took $(( $(date +%s) - start )) s"

size_tool="$(command -v avr-size || true)"
for env in "${ENVS[@]}"; do
  out="$PLATFORMIO_BUILD_DIR/$env"
  cp "$out/firmware.elf" "$ELF_DIR/strider_firmware_$env.elf"
  [ -f "$out/firmware.hex" ] && cp "$out/firmware.hex" "$ELF_DIR/strider_firmware_$env.hex"
  if [ -n "$size_tool" ]; then
    echo "strider_firmware_$env.elf ($MODE PlatformIO build):"
    "$size_tool" --format=avr --mcu=atmega2560 "$ELF_DIR/strider_firmware_$env.elf" |
      grep -E '^(Program|Data):'
  fi
done
log "ELFs in $ELF_DIR"
