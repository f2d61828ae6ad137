#!/usr/bin/env bash
# The Arduino IDE's path, offline: compiles every sketch of lib/strider/examples
# for the Mega 2560 (FQBN arduino:avr:mega) with arduino-cli, the Arduino
# IDE's own build engine, with Strider installed as a sketchbook library the
# way a user installs it, and prints each sketch's flash and RAM use. With
# STRIDER_VBENCH (tools/vbench) each example then runs on the simulated Mega
# and what it prints or drives is checked.
#
#   tools/arduino/arduino_cli.sh [sketch dir...]   (default: every example)
#
# What it puts together, all under STRIDER_ARDUINO_DIR (default
# out/build/arduino, where tools/dev and the ctest test put it too):
# - arduino-cli ARDUINO_CLI_VERSION, built once from the Go module proxy
#   (bin/; later runs reuse it). `go install module@version` refuses it (its
#   go.mod has a replace directive), so its module is downloaded and built;
# - a sketchbook whose hardware/arduino/avr is the pinned ArduinoCore-avr
#   1.8.8 of STRIDER_THIRD_PARTY (links to its files) plus a
#   platform.local.txt with the one line users add (-std=gnu++14), and whose
#   libraries/ are lib/strider and the pinned Adafruit PWM Servo Driver and
#   BusIO libraries (links);
# - a data folder with empty package and library indexes: arduino-cli
#   downloads both on first use otherwise, and needs neither to compile for
#   a platform in the sketchbook.
# The toolchain is the avr-gcc on PATH (Debian's 5.4; the IDE ships 7.3), and
# Universal Ctags stands in for the IDE's ctags (tools/arduino/ctags_compat.sh).
#
# Exit status: 0 all compiled (and ran), 1 a failure or a warning from the
# library or a sketch, 77 skipped (no third_party folder, no Go, no avr-gcc or
# Universal Ctags, or the Go module proxy out of reach).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
# The release, and its tag's commit for `arduino-cli version`. 1.0.4 is the
# newest release the Go module proxy served when this was written (it refused
# each of 1.1.0 to 1.3.1 that was tried).
ARDUINO_CLI_VERSION=1.0.4
ARDUINO_CLI_COMMIT=a0d912d
ARDUINO_CLI_MODULE=github.com/arduino/arduino-cli
FQBN=arduino:avr:mega:cpu=atmega2560
WORK="${STRIDER_ARDUINO_DIR:-$ROOT/out/build/arduino}"

log() { printf '[arduino] %s\n' "$*"; }
skip() { printf '[arduino] SKIPPED: %s\n' "$*"; exit 77; }

# tools/dev exports STRIDER_THIRD_PARTY (empty when there is no such folder);
# run on its own, look where tools/dev looks.
if [ -z "${STRIDER_THIRD_PARTY+set}" ]; then
  STRIDER_THIRD_PARTY="$ROOT/../shared/third_party"
  [ -d "$STRIDER_THIRD_PARTY" ] && STRIDER_THIRD_PARTY="$(cd "$STRIDER_THIRD_PARTY" && pwd)" || STRIDER_THIRD_PARTY=""
fi
TP="$STRIDER_THIRD_PARTY"
[ -n "$TP" ] || skip "no third_party folder (STRIDER_THIRD_PARTY is empty): the Arduino core and the Adafruit libraries come from there"
CORE="$TP/ArduinoCore-avr"
LIBS=("$ROOT/lib/strider:Strider"
      "$TP/Adafruit-PWM-Servo-Driver-Library:Adafruit_PWM_Servo_Driver_Library"
      "$TP/Adafruit_BusIO:Adafruit_BusIO")
[ -f "$CORE/platform.txt" ] || skip "$CORE/platform.txt missing"
for l in "${LIBS[@]}"; do [ -f "${l%%:*}/library.properties" ] || skip "${l%%:*} missing"; done
command -v avr-gcc >/dev/null || skip "no avr-gcc (tools/dev setup installs gcc-avr)"
case "$(ctags --version 2>/dev/null || true)" in
  *"Universal Ctags"*) ;;
  *) skip "no Universal Ctags (tools/dev setup installs universal-ctags)" ;;
esac

CLI="$WORK/bin/arduino-cli-$ARDUINO_CLI_VERSION"

# ---- arduino-cli, built once ------------------------------------------------
build_cli() {
  command -v go >/dev/null || skip "no Go toolchain (go) to build arduino-cli $ARDUINO_CLI_VERSION"
  # Its own module and build caches, writable so that `rm -rf out` works.
  export GOPATH="$WORK/go" GOMODCACHE="$WORK/go/mod" GOCACHE="$WORK/go/cache"
  export GOFLAGS="${GOFLAGS:-} -modcacherw" GOTOOLCHAIN=local
  local t0 dir
  t0=$(date +%s)
  mkdir -p "$WORK/bin"
  log "building arduino-cli $ARDUINO_CLI_VERSION with $(go version | cut -d' ' -f3) (once: 1-2 min, 650 MB of modules and build cache, removed afterwards)"
  dir=$(cd "$WORK" && go mod download -json "$ARDUINO_CLI_MODULE@v$ARDUINO_CLI_VERSION" | sed -n 's/^[[:space:]]*"Dir": "\(.*\)",$/\1/p') || true
  [ -n "$dir" ] && [ -f "$dir/go.mod" ] ||
    skip "could not download $ARDUINO_CLI_MODULE@v$ARDUINO_CLI_VERSION from the Go module proxy ($(go env GOPROXY))"
  if ! (cd "$dir" && go mod download) >"$WORK/go-download.log" 2>&1; then
    tail -5 "$WORK/go-download.log"
    skip "could not download arduino-cli's dependencies from the Go module proxy"
  fi
  (cd "$dir" && go build -trimpath -o "$CLI.tmp" -ldflags "-s -w \
      -X $ARDUINO_CLI_MODULE/version.versionString=$ARDUINO_CLI_VERSION \
      -X $ARDUINO_CLI_MODULE/version.commit=$ARDUINO_CLI_COMMIT" .)
  mv "$CLI.tmp" "$CLI"
  # The binary is all that is kept: the module and build caches (about 650 MB)
  # only serve another build.
  go clean -cache -modcache
  rm -rf "$WORK/go" "$WORK/go-download.log"
  log "built $CLI in $(( $(date +%s) - t0 )) s"
}
if [ -x "$CLI" ]; then log "arduino-cli $ARDUINO_CLI_VERSION: cached ($CLI)"; else build_cli; fi

# ---- sketchbook, data folder, configuration (rebuilt every run: links only) --
SKETCHBOOK="$WORK/sketchbook"
DATA="$WORK/data"
rm -rf "$SKETCHBOOK"
mkdir -p "$SKETCHBOOK/hardware/arduino/avr" "$SKETCHBOOK/libraries" "$DATA" "$WORK/downloads" "$WORK/cache"
for f in "$CORE"/*; do ln -s "$f" "$SKETCHBOOK/hardware/arduino/avr/"; done
# The one line README.md tells users to add: the library is C++14, core
# 1.8.8 compiles C++ as gnu++11.
echo 'compiler.cpp.extra_flags=-std=gnu++14' >"$SKETCHBOOK/hardware/arduino/avr/platform.local.txt"
for l in "${LIBS[@]}"; do ln -s "${l%%:*}" "$SKETCHBOOK/libraries/${l##*:}"; done
[ -f "$DATA/package_index.json" ] || echo '{"packages": []}' >"$DATA/package_index.json"
[ -f "$DATA/library_index.json" ] || echo '{"libraries": []}' >"$DATA/library_index.json"
CONFIG="$WORK/arduino-cli.yaml"
cat >"$CONFIG" <<EOF
directories:
  data: $DATA
  user: $SKETCHBOOK
  downloads: $WORK/downloads
build_cache:
  path: $WORK/cache
updater:
  enable_notification: false
EOF

# ---- build properties for this machine's toolchain ---------------------------
# compiler.path: platform.txt wants the avr-gcc tool of the Arduino package
# index ({runtime.tools.avr-gcc.path}); here it is the one on PATH.
PROPS=(--build-property "compiler.path=$(dirname "$(command -v avr-gcc)")/"
       --build-property "tools.ctags.cmd.path=$ROOT/tools/arduino/ctags_compat.sh")
# gcc 5.4's float.h has no DECIMAL_DIG in C++, which the core's WString.cpp uses.
case "$(avr-gcc -dumpversion)" in
  5.*) PROPS+=(--build-property "build.extra_flags=-DDECIMAL_DIG=__DECIMAL_DIG__") ;;
esac

# ---- run on the virtual Mega -------------------------------------------------
# With STRIDER_VBENCH (tools/vbench's binary, as the ctest test passes it) each
# compiled example also runs on the simulated ATmega2560, and what it prints
# or drives is checked. 0 passed, 1 failed, 2 no check for this sketch.
VBENCH="${STRIDER_VBENCH:-}"
run_example() {
  local name="$1" elf="$2" log="$WORK/logs/$1.run.txt" pulses="$WORK/logs/$1.pulses.csv"
  case "$name" in
    LegIK)
      "$VBENCH" --elf "$elf" --duration 0.2 >"$log" 2>&1 || return 1
      # hexapod18's standing foot (robots/hexapod18.h: t2 +1.95, t3 -89.64
      # deg) in both scalars, FK back to a foot, a foot out of reach.
      grep -q 'float foot (120, 0, -90) mm: ok, t1 0.00 t2 1.95 t3 -89.64 deg' "$log" &&
        grep -q 'Fixed foot (120, 0, -90) mm: ok, t1 0.00 t2 1.95 t3 -89.64 deg' "$log" &&
        grep -q 'fk(Fixed joints) = (140.00, 30.00, -60.00) mm' "$log" &&
        grep -q 'Fixed foot (350, 0, 0) mm: unreachable' "$log"
      ;;
    OneLegServo)
      "$VBENCH" --elf "$elf" --duration 2.2 --pulses "$pulses" >"$log" 2>&1 || return 1
      # The coxa (output 0) sweeps about +-9.5 deg (y +-20 mm at 120 mm out),
      # +-105 us about 1500 us; femur and tibia (1, 2) move a little; nothing else.
      awk -F, 'NR > 1 { n[$2]++; if (!($2 in lo) || $3 < lo[$2]) lo[$2] = $3; if ($3 > hi[$2]) hi[$2] = $3 }
        END { k = 0; for (c in n) k++; exit !(k == 3 && n[0] > 50 && lo[0] < 1420 && hi[0] > 1580 && (1 in n) && (2 in n)) }' "$pulses"
      ;;
    *) return 2 ;;
  esac
}

# ---- compile ----------------------------------------------------------------
if [ "$#" -gt 0 ]; then SKETCHES=("$@"); else SKETCHES=("$ROOT"/lib/strider/examples/*/); fi
log "$("$CLI" --config-file "$CONFIG" --no-color version | head -1); avr-gcc $(avr-gcc -dumpversion); core: $CORE"
failed=0
summary=()
for dir in "${SKETCHES[@]}"; do
  dir="${dir%/}"
  name="$(basename "$dir")"
  out="$WORK/logs/$name.txt"
  mkdir -p "$WORK/logs"
  log "compile $name for $FQBN"
  # The whole output goes to logs/; on a failure it is printed, less the
  # "discovery builtin:... not found" lines: the serial and mDNS port
  # discoveries are tools of the package index that only uploads need.
  if "$CLI" --config-file "$CONFIG" compile --no-color --fqbn "$FQBN" --warnings all --output-dir "$WORK/sketches/$name" "${PROPS[@]}" "$dir" >"$out" 2>&1; then
    status=ok
  else
    status=FAILED
    failed=1
  fi
  # Warnings from the library or the sketch fail the run (the core's own are
  # left to the core).
  if grep -E '(/libraries/Strider/|/examples/'"$name"'/).*warning:' "$out" >/dev/null; then
    status="FAILED (warnings)"
    failed=1
  fi
  if [ "$status" = ok ]; then
    grep -E '^(Sketch uses|Global variables)' "$out" | sed 's/^/  /'
  else
    grep -v 'discovery builtin:[a-z-]* not found' "$out" || true
  fi
  run="-"
  if [ "$status" = ok ] && [ -n "$VBENCH" ]; then
    if [ ! -x "$VBENCH" ]; then
      run="no vbench"
    else
      rc=0
      run_example "$name" "$WORK/sketches/$name/$name.ino.elf" || rc=$?
      case "$rc" in
        0) run="ran ok" ;;
        2) run="no check" ;;
        *) run="RUN FAILED"; failed=1; log "$name on the virtual Mega:"; cat "$WORK/logs/$name.run.txt" ;;
      esac
    fi
  fi
  flash=$(sed -n 's/^Sketch uses \([0-9]*\) bytes.*/\1/p' "$out")
  ram=$(sed -n 's/^Global variables use \([0-9]*\) bytes.*/\1/p' "$out")
  summary+=("$(printf '%-14s %-8s flash %6s B  RAM %5s B  %s' "$name" "$status" "${flash:--}" "${ram:--}" "$run")")
done
log "arduino-cli $ARDUINO_CLI_VERSION, $FQBN, ArduinoCore-avr 1.8.8, avr-gcc $(avr-gcc -dumpversion):"
for s in "${summary[@]}"; do printf '  %s\n' "$s"; done
exit "$failed"
