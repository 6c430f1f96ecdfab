#!/usr/bin/env bash
# Footprint of the small-robot firmware's communication core (./touchline footprint):
#  1. cross-compiles the core for Cortex-M3 (arm-none-eabi-gcc -Os -mcpu=cortex-m3 -mthumb,
#     -ffunction-sections -fdata-sections -fstack-usage -fcallgraph-info=su), links it with
#     the board port (board/board_main.c) using --gc-sections and newlib-nano, and prints
#     code size, static RAM and the worst-case stack per entry point;
#  2. measures the encode-and-send cost per byte on the host with valgrind's callgrind and
#     scales the instruction count to 72 MHz (compare: the thesis' 0.039 ms/byte);
#  3. measures the reliable stream's throughput and retransmissions at 0/10/30% loss.
# Options: --no-callgrind, --no-reliable.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
OUT="${FOOTPRINT_OUT:-$ROOT/robot-side/build/footprint}"
HOSTBUILD="${FOOTPRINT_HOSTBUILD:-$ROOT/robot-side/build}"
RUN_CALLGRIND=1
RUN_RELIABLE=1
for a in "$@"; do
  case "$a" in
    --no-callgrind) RUN_CALLGRIND=0 ;;
    --no-reliable) RUN_RELIABLE=0 ;;
    *) echo "usage: footprint.sh [--no-callgrind] [--no-reliable]" >&2; exit 2 ;;
  esac
done
need() { command -v "$1" >/dev/null || { echo "footprint: $1 not found (install: $2)" >&2; exit 1; }; }
need arm-none-eabi-gcc "gcc-arm-none-eabi libnewlib-arm-none-eabi"
need nanopb_generator.py "nanopb python3-protobuf"
need python3 python3

rm -rf "$OUT" && mkdir -p "$OUT/gen" "$OUT/obj"
nanopb_generator.py -q -I "$ROOT/proto" -f "$HERE/fumanoid.options" -D "$OUT/gen" "$ROOT/proto/fumanoid.proto"

# The board is built with a team key (a fixed, public test key: only its size matters here),
# so the verifier (fw_auth + libsodium's HMAC-SHA-256) is in the image and on the receive path.
python3 - "$OUT/gen/team_key.h" <<'PY'
import sys
key = ", ".join(f"0x{(i * 37 + 11) & 0xff:02x}" for i in range(32))
open(sys.argv[1], "w").write('#include "fw_auth.h"\nstatic const fw_team_key touchline_team_key = {{'
                             + key + '}, {0x01, 0x02, 0x03, 0x04}};\n')
PY
CFLAGS=(-std=c99 -Os -mcpu=cortex-m3 -mthumb -DFW_LOG_NONE -ffunction-sections -fdata-sections -fstack-usage
        -fcallgraph-info=su -Wall -Wextra -I"$HERE/src" -I"$HERE/third_party/nanopb"
        -I"$HERE/third_party/libsodium/include" -I"$OUT/gen")
CORE=("$HERE"/src/fw_{framing,registry,gamecontroller,reliable,wlan,robot,gs1500,auth,digest}.c
      "$HERE"/third_party/libsodium/{auth_hmacsha256,hash_sha256_cp,verify,sodium_glue}.c
      "$HERE"/third_party/nanopb/pb_{common,encode,decode}.c "$OUT/gen/fumanoid.pb.c" "$HERE/board/board_main.c"
      "$HERE/board/board_boot.c")
echo "footprint: $(arm-none-eabi-gcc --version | head -1)" >&2
for f in "${CORE[@]}"; do
  extra=()
  case "$f" in
    */board_main.c) extra=(-DTOUCHLINE_TEAM_KEY_HEADER='"team_key.h"') ;;
    */third_party/libsodium/*.c) extra=(-DCONFIGURED=1 -DSODIUM_STATIC) ;; # as libsodium's own build
  esac
  arm-none-eabi-gcc "${CFLAGS[@]}" "${extra[@]}" -c "$f" -o "$OUT/obj/$(basename "$f" .c).o"
done
arm-none-eabi-gcc -mcpu=cortex-m3 -mthumb -Os -specs=nano.specs -specs=nosys.specs -Wl,--gc-sections \
  -Wl,-Map="$OUT/firmware.map" "$OUT"/obj/*.o -o "$OUT/firmware.elf"
echo
arm-none-eabi-size "$OUT/firmware.elf"
echo
status=0
python3 "$HERE/tools/footprint_report.py" "$OUT" "$OUT/gen/fumanoid.pb.h" || status=$?

if [ "$RUN_CALLGRIND" = 1 ] || [ "$RUN_RELIABLE" = 1 ]; then
  # Always brought up to date (cheap when it is): a benchmark binary older than the sources
  # measured the old code (the tag's cost was once reported for the previous algorithm).
  echo "footprint: building the host benchmarks (robot-side/build)" >&2
  [ -f "$HOSTBUILD/CMakeCache.txt" ] || cmake -S "$ROOT/robot-side" -B "$HOSTBUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
  cmake --build "$HOSTBUILD" --target fw_encode_bench fw_reliable_bench fw_auth_bench -j 2 >/dev/null
fi
if [ "$RUN_CALLGRIND" = 1 ]; then
  echo
  if command -v valgrind >/dev/null; then
    python3 "$HERE/tools/encode_cost.py" "$HOSTBUILD/bin/fw_encode_bench" "$OUT"
    echo
    python3 "$HERE/tools/auth_cost.py" "$HOSTBUILD/bin/fw_auth_bench" "$OUT"
  else
    echo "footprint: valgrind not found, encode cost skipped" >&2
  fi
fi
if [ "$RUN_RELIABLE" = 1 ]; then
  echo
  "$HOSTBUILD/bin/fw_reliable_bench"
fi
exit $status
